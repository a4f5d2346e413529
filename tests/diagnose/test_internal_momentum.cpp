// `internal_momentum` (issue 31, item 1): a rotor inside, h fixed in body axes.
//   - the model: the diagnosis's gyrostat against the generator's independent integrator;
//   - its equivalence: on a body of revolution, h along the axis is, within one flight, an
//     axial moment changed by h / w_axis, exactly; not with a transverse h, and not
//     across flights at different axial rates;
//   - the diagnosis: rotor sessions named a rotor, look-alike sessions (impulses, moments
//     on bodies of revolution, filtered noise, gyro biases, the stopped wheel: wrong moments
//     on every body) never, and a rotor with wrong moments named in >= 90 % of its sessions
//     (4_judge/told_apart.hpp, 4_judge/joint_candidates.hpp; docs/diagnose.md, "A rotor
//     inside").
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "diagnose/1_input/flight_input.hpp"
#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/2_model/flight_model.hpp"
#include "diagnose/2_model/momentum_from_readings.hpp"
#include "common/printf_text.hpp"
#include "diagnose/4_judge/between_flight_scatter.hpp"
#include "diagnose/4_judge/momentum_moment_equivalence.hpp"
#include "diagnose/5_flow/diagnosis.hpp"
#include "generator/perturbed_rigid_body.hpp"
#include "generator/rotor_cases.hpp"

using namespace aloft::host;
using namespace aloft::host::diagnose;

namespace {

// Noise-free body-axis readings of the generator's body (1 kHz, 1 s) with a rotor h.
Flight gyrostat_flight(const Eigen::Matrix3d& tensor, const Eigen::Vector3d& h, const Eigen::Vector3d& w0) {
  aloft::generator::FlightPhysics physics;
  physics.inertia_kg_m2 = tensor;
  physics.internal_momentum_N_m_s = h;
  const aloft::generator::PerturbedRigidBody body(physics);
  aloft::generator::FlightState start;
  start.omega_body = w0;
  Flight flight;
  for (int k = 0; k <= 1000; ++k) flight.time_s.push_back(k * 1e-3);
  for (const auto& s : body.sample(start, flight.time_s)) flight.omega.push_back(s.omega_body);
  flight.usable.assign(flight.size(), 1);
  return flight;
}

// The diagnosis's prediction of `flight` under `model` with theta, from the first sample's rate.
std::vector<Eigen::Vector3d> predicted(const EffectModel& model, const Flight& flight,
                                       const Eigen::VectorXd& theta) {
  std::vector<Eigen::Vector3d> out;
  predict_readings(model, flight, 0, flight.omega.front(), theta, out);
  return out;
}

double largest_gap(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::max(worst, (a[k] - b[k]).norm());
  return worst;
}

// inertia_moments' theta (effects/inertia_moments.cpp) for moments `m` of any scale.
Eigen::VectorXd moments_theta(const NominalInertia& nominal, const Eigen::Vector3d& m) {
  const Eigen::Vector3d u = m.cwiseQuotient(nominal.principal_moments).array().log().matrix();
  Eigen::VectorXd theta(2);
  theta << u(0) - u.mean(), u(1) - u.mean();
  return theta;
}

// How close the model must follow an independent integrator: at 1 kHz the model shares one
// RK4 step between samples up to 5 ms apart (2_model/flight_model.cpp, ReadingWalks),
// within 1.6e-6 rad/s of a step a sample (tests/diagnose/test_flight_model.cpp); a gyro's
// noise is 0.005-0.02 rad/s.
constexpr double kModelAgreement_rad_s = 1e-5;

const Eigen::Matrix3d kDisc = Eigen::Vector3d(0.0037, 0.0037, 0.0072).asDiagonal();

}  // namespace

TEST_CASE("the gyrostat model moves as the generator's independent integrator does", "[rotor]") {
  const Eigen::Matrix3d tensor = Eigen::Vector3d(0.0017, 0.0042, 0.0054).asDiagonal();
  const Eigen::Vector3d h(0.0012, -0.0030, 0.0021), w0(4.0, -6.0, 7.0);
  const Flight flight = gyrostat_flight(tensor, h, w0);
  const NominalInertia nominal = NominalInertia::of_tensor(tensor);
  const Eigen::VectorXd theta = tensor.inverse() * h;
  const double gap =
      largest_gap(predicted(EffectModel(Effect::internal_momentum, nominal), flight, theta), flight.omega);
  std::printf("gyrostat: model against generator within %.2g rad/s over 1 s\n", gap);
  CHECK(gap < kModelAgreement_rad_s);
  // and the rotor matters: the rigid body drifts away by far more.
  CHECK(largest_gap(predicted(EffectModel(Effect::none, nominal), flight, Eigen::VectorXd()), flight.omega) >
        0.1);
}

TEST_CASE("a rotor's h read off the readings by the balance of the Euler equations", "[rotor][start]") {
  const Eigen::Matrix3d tensor = Eigen::Vector3d(0.0017, 0.0042, 0.0054).asDiagonal();
  const NominalInertia nominal = NominalInertia::of_tensor(tensor);
  // A large rotor (|h| about 30 % of |L|): from zero its fit can stop in another minimum.
  const Eigen::Vector3d h(0.0060, -0.0150, 0.0105), w0(4.0, -6.0, 7.0);
  const Flight flight = gyrostat_flight(tensor, h, w0);
  const Eigen::VectorXd theta = momentum_theta_from_readings({&flight}, nominal);
  const Eigen::Vector3d read_h = tensor * theta;
  std::printf("h from the readings: %.3g %% off\n", 100.0 * (read_h - h).norm() / h.norm());
  CHECK((read_h - h).norm() < 0.01 * h.norm());  // noise-free: only the central differences err
  // Two flights share h: their balance pooled reads it too.
  const Flight other = gyrostat_flight(tensor, h, Eigen::Vector3d(-9.0, 2.0, 3.0));
  CHECK((tensor * momentum_theta_from_readings({&flight, &other}, nominal) - h).norm() < 0.01 * h.norm());
  // A spin about one principal axis and no rotor: w × h cannot see h along the axis, and
  // the ridge keeps the answer finite (zero).
  const Flight spin = gyrostat_flight(tensor, Eigen::Vector3d::Zero(), Eigen::Vector3d(0.0, 0.0, 8.0));
  const Eigen::VectorXd still = momentum_theta_from_readings({&spin}, nominal);
  REQUIRE(still.allFinite());
  CHECK(still.norm() < 1e-6);
}

// The body file's rotor (SPEC §2) and the log's rotor_rad_s (§3) give the flight the wheel's h
// at its last sample, which the report sets beside a rotor it finds; without either, nothing.
TEST_CASE("a flight carries the log's rotor at its end", "[rotor]") {
  ImuLog log;
  for (int k = 0; k < 10; ++k) {
    log.time_s.push_back(0.001 * k);
    log.gyro_rad_s.push_back(Eigen::Vector3d(1.0, 2.0, 3.0));
    log.rotor_rad_s.push_back(20.0 * k);  // rad/s, spinning up
  }
  Body body;
  body.rotor = BodyRotor{2e-4, Eigen::Vector3d(0.0, 0.6, 0.8)};
  const Flight flight = flight_from_imu(log, body, 0.0, 0.0065, "f");  // samples 0-6
  REQUIRE(flight.logged_rotor_h_N_m_s);
  CHECK((*flight.logged_rotor_h_N_m_s - 2e-4 * 120.0 * Eigen::Vector3d(0.0, 0.6, 0.8)).norm() < 1e-15);
  CHECK_FALSE(flight_from_imu(log, Body(), 0.0, 1.0, "no rotor").logged_rotor_h_N_m_s);
  log.rotor_rad_s.clear();
  CHECK_FALSE(flight_from_imu(log, body, 0.0, 1.0, "no speed").logged_rotor_h_N_m_s);
}

TEST_CASE("on a body of revolution, a rotor along the axis is an axial moment change within a flight",
          "[rotor][equivalence]") {
  const NominalInertia nominal = NominalInertia::of_tensor(kDisc);
  const Eigen::Vector3d h(0.0, 0.0, 0.0009);  // 5 % of |L| at ~10 rad/s
  const Eigen::Vector3d w0(6.0, -3.0, 8.0);
  const Flight flight = gyrostat_flight(kDisc, h, w0);
  const auto moments = moments_mimicking_momentum(nominal, h, w0(2));
  REQUIRE(moments.has_value());
  CHECK((*moments)(2) == Approx(0.0072 + 0.0009 / 8.0));
  const std::vector<Eigen::Vector3d> rotor =
      predicted(EffectModel(Effect::internal_momentum, nominal), flight, kDisc.inverse() * h);
  const std::vector<Eigen::Vector3d> axial =
      predicted(EffectModel(Effect::inertia_moments, nominal), flight, moments_theta(nominal, *moments));
  const double same = largest_gap(rotor, axial);
  std::printf("rotor along the axis vs axial moment + h/w_a: %.2g rad/s apart over 1 s\n", same);
  CHECK(same < 1e-12);
  CHECK(largest_gap(rotor, flight.omega) < kModelAgreement_rad_s);

  SECTION("not with a transverse rotor") {
    const Eigen::Vector3d tilted(0.0003, 0.0, 0.0009);
    CHECK_FALSE(moments_mimicking_momentum(nominal, tilted, w0(2)).has_value());
    const Flight f = gyrostat_flight(kDisc, tilted, w0);
    const auto best = moments_mimicking_momentum(nominal, Eigen::Vector3d(0, 0, 0.0009), w0(2));
    CHECK(largest_gap(
              predicted(EffectModel(Effect::inertia_moments, nominal), f, moments_theta(nominal, *best)),
              f.omega) > 0.05);
  }
  SECTION("not across flights at different axial rates") {
    const Eigen::Vector3d w1(6.0, -3.0, 4.0);  // half the axial rate
    const Flight other = gyrostat_flight(kDisc, h, w1);
    // The moments that mimic the first flight's rotor miss the second flight.
    CHECK(largest_gap(predicted(EffectModel(Effect::inertia_moments, nominal), other,
                                moments_theta(nominal, *moments)),
                      other.omega) > 0.05);
  }
  SECTION("not on a body whose moments all differ") {
    const NominalInertia box =
        NominalInertia::of_tensor(Eigen::Vector3d(0.0017, 0.0042, 0.0054).asDiagonal());
    CHECK_FALSE(moments_mimicking_momentum(box, Eigen::Vector3d(0, 0, 0.001), 5.0).has_value());
  }
}

namespace {

// Seeds of generator/rotor_cases.hpp: the withheld set unless ALOFT_ROTOR_SEEDS=tuning
// (the set the rule of 4_judge/told_apart.hpp was tuned on) or =fresh (a set measured
// once, after the large rotor's starts were repaired on failures of the other two).
aloft::generator::RotorSeeds rotor_seeds() {
  const char* set = std::getenv("ALOFT_ROTOR_SEEDS");
  const std::string name = set != nullptr ? set : "";
  if (name == "tuning") return aloft::generator::RotorSeeds::tuning;
  if (name == "fresh") return aloft::generator::RotorSeeds::fresh;
  return aloft::generator::RotorSeeds::withheld;
}

// Sessions of each kind: 5, or ALOFT_ROTOR_SESSIONS (a larger one-off measurement).
int sessions_per_kind() {
  const char* count = std::getenv("ALOFT_ROTOR_SESSIONS");
  return count != nullptr ? std::max(1, std::atoi(count)) : 5;
}

// A session's kind: its name without the index ("rotor_moments_3" -> "rotor_moments").
std::string kind_of(const aloft::generator::SessionCase& c) { return c.name.substr(0, c.name.rfind('_')); }

// Only the kinds ALOFT_ROTOR_KINDS lists (comma-separated, e.g. "rotor_moments,stopped":
// a quicker one-off measurement of a few); every kind when unset.
bool kind_wanted(const std::string& kind) {
  const char* kinds = std::getenv("ALOFT_ROTOR_KINDS");
  if (kinds == nullptr) return true;
  const std::string list = std::string(",") + kinds + ",";
  return list.find("," + kind + ",") != std::string::npos;
}

const VerdictEffect* named_rotor(const Verdict& v) {
  for (const VerdictEffect& e : v.effects) {
    // Steady or spun up: both report as internal_momentum.
    if (std::string(effect_name(e.effect)) == "internal_momentum") return &e;
  }
  return nullptr;
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / 3.14159265358979323846;
}

// The pooled verdict's effects, in the report's order.
std::string effects_text(const Verdict& v) {
  std::string out;
  for (const VerdictEffect& e : v.effects) out += std::string(out.empty() ? "" : "+") + effect_name(e.effect);
  return out.empty() ? std::string("none") : out;
}

// The true h of a generated rotor flight (a compound flight keeps each effect's
// parameters under its name).
Eigen::Vector3d true_h(const aloft::generator::GeneratedFlight& flight) {
  const nlohmann::json& params = flight.truth.params.contains("internal_momentum")
                                     ? flight.truth.params.at("internal_momentum")
                                     : flight.truth.params;
  const nlohmann::json& h = params.at("h_N_m_s");
  return Eigen::Vector3d(h[0].get<double>(), h[1].get<double>(), h[2].get<double>());
}

// What one kind of session came to.
struct KindTally {
  bool rotor = false;  // a rotor is in every flight
  int sessions = 0, named = 0, h_right = 0, confident = 0;
  int alone = 0;  // sessions whose pooled verdict is the rotor and nothing else
  int flights = 0, flights_listed = 0;
  // Sessions with a tensor report; its 95 % intervals hold the truth; its ratios within 1 % of it.
  int tensors = 0, tensors_covered = 0, tensors_close = 0;
};

// The true moment ratios (tensor_report.hpp's: I2/I1 and I3/I1 in body order along the
// nominal principal axes) of a generated flight.
Eigen::Vector2d true_ratios(const aloft::generator::GeneratedFlight& flight, const NominalInertia& nominal) {
  const Eigen::Matrix3d axes = nominal.principal_axes.toRotationMatrix();
  const Eigen::Vector3d moments = (axes.transpose() * flight.true_inertia_kg_m2 * axes).diagonal();
  const Eigen::Vector3i order = principal_axis_order(nominal);
  return Eigen::Vector2d(moments(order(1)) / moments(order(0)), moments(order(2)) / moments(order(0)));
}

// The tensor report's ratios against the truth, and whether its 95 % intervals hold it.
std::string tensor_against_truth(const TensorReport& t, const Eigen::Vector2d& truth, KindTally& tally) {
  bool covered = true;
  for (int i = 0; i < 2; ++i) covered = covered && truth(i) >= t.ratio_low(i) && truth(i) <= t.ratio_high(i);
  ++tally.tensors;
  tally.tensors_covered += covered;
  tally.tensors_close +=
      (t.ratio_best.cwiseQuotient(truth) - Eigen::Vector2d::Ones()).cwiseAbs().maxCoeff() <= 0.01;
  return printf_text("; tensor ratios %+.2f %+.2f %% off the truth",
                     100.0 * (t.ratio_best(0) / truth(0) - 1.0), 100.0 * (t.ratio_best(1) / truth(1) - 1.0)) +
         (covered ? ", inside its 95 % intervals" : ", OUTSIDE its 95 % intervals");
}

// The rotor fitted with other effects in a session (`own`: its flights' own analyses):
// with the moments at the first step (joint_candidates.hpp: its flights' scatter, its score
// behind the first step's choice, and how much it shrinks the held-out error of the rotor
// alone and of the moments alone), and on each later step's base (the scatter).
std::string rotor_with_others(const Analysis& pooled, const std::vector<const Analysis*>& own) {
  double alone_rotor = 0.0, alone_moments = 0.0;
  for (const Candidate& a : pooled.candidates) {
    if (a.base.empty() && a.effect == Effect::internal_momentum) alone_rotor = a.heldout_rms_rel_err;
    if (a.base.empty() && a.effect == Effect::inertia_moments) alone_moments = a.heldout_rms_rel_err;
  }
  std::string out;
  for (const Candidate& r : pooled.candidates) {
    if (r.effect != Effect::internal_momentum || r.base.empty()) continue;
    const auto s = between_flight_scatter(r, own);
    out += printf_text(
        ", with the moments %.3g (score behind %.1f, spread %.1f; shrinks the rotor's error by %.3f, the "
        "moments' by %.3f)",
        s ? s->chi_square_per_dof : -1.0, r.score_behind, r.score_behind_spread,
        1.0 - r.heldout_rms_rel_err / alone_rotor, 1.0 - r.heldout_rms_rel_err / alone_moments);
  }
  for (const ModelStep& step : pooled.steps) {
    for (const Candidate& r : step.candidates) {
      if (r.effect != Effect::internal_momentum || r.base.empty() || r.reference) continue;
      const auto s = between_flight_scatter(r, own);
      out += std::string(", on ") + effect_name(r.base.back()) +
             printf_text(" %.3g", s ? s->chi_square_per_dof : -1.0);
    }
  }
  return out;
}

// One session diagnosed, a line printed, and its kind's tally counted.
void judge_session(const aloft::generator::SessionCase& c, KindTally& tally) {
  namespace gen = aloft::generator;
  std::vector<Flight> flights;
  std::vector<gen::GeneratedFlight> generated;
  for (const gen::FlightSpec& spec : c.flights) {
    generated.push_back(gen::generate_flight(spec, c.seed));
    flights.push_back(flight_from_imu(generated.back().imu, generated.back().body, -INFINITY, INFINITY,
                                      c.name + "_" + std::to_string(flights.size())));
  }
  const NominalInertia nominal = NominalInertia::of(generated.front().body.inertia);
  const SessionDiagnosis d = diagnose_session(flights, nominal, 2);
  tally.rotor = c.flights.front().effect == "internal_momentum";
  const VerdictEffect* named = named_rotor(d.pooled.verdict);
  int flights_listed = 0;
  for (const FlightDiagnosis& f : d.flights) {
    const auto& listed = f.analysis.verdict.indistinguishable;
    flights_listed += std::find(listed.begin(), listed.end(), Effect::internal_momentum) != listed.end();
  }
  ++tally.sessions;
  tally.named += named != nullptr;
  tally.confident += named != nullptr && d.pooled.verdict.confident;
  tally.alone += named != nullptr && d.pooled.verdict.effects.size() == 1;
  tally.flights += static_cast<int>(flights.size());
  tally.flights_listed += flights_listed;
  std::string detail;
  if (tally.rotor && named != nullptr) {
    const Eigen::Vector3d truth = true_h(generated.front());
    const double size = named->params.vector.norm() / truth.norm() - 1.0;
    const double turn = angle_deg(named->params.vector, truth);
    tally.h_right += std::abs(size) <= 0.10 && turn <= 10.0;
    detail = printf_text(" |h| %+.1f %%, direction %.1f deg", 100.0 * size, turn);
    const auto& why = d.pooled.verdict.could_not_judge;
    if (!why.empty()) detail += " (not confident: " + why.front() + ")";
    if (d.pooled.tensor)
      detail += tensor_against_truth(*d.pooled.tensor, true_ratios(generated.front(), nominal), tally);
  }
  std::vector<const Analysis*> own;
  for (const FlightDiagnosis& f : d.flights) own.push_back(&f.analysis);
  const auto scatter = between_flight_scatter(Effect::internal_momentum, own);
  const std::string on_base = rotor_with_others(d.pooled, own);
  std::printf(
      "%-16s %-10s -> %-40s%s%s; flights listing a rotor beside the headline %d of %zu; rotor "
      "scatter %.3g%s\n",
      c.name.c_str(), c.flights.front().body.c_str(), effects_text(d.pooled.verdict).c_str(),
      d.pooled.verdict.confident ? " confident" : "", detail.c_str(), flights_listed, flights.size(),
      scatter ? scatter->chi_square_per_dof : -1.0, on_base.c_str());
}

}  // namespace

// A rotor with wrong moments too (kind rotor_moments): named in 5 of 5 sessions on the
// tuning seeds and 5 of 5 on the withheld ones, once the rotor and the moments are also
// tried together at the first step (joint_candidates.hpp; before, 3 of 5 on each: where the
// rotor outweighs the moment error neither leads alone). Held to issue 31's bar for rotor
// sessions, which at 5 sessions means all 5.
constexpr double kRotorWithWrongMomentsNamed = 0.9;
// A larger rotor with wrong moments (kind large_rotor_moments): 4 of 5 sessions on the
// withheld seeds, the lowest of the three sets (above); below issue 31's bar, which it
// was not set for.
constexpr double kLargeRotorWithWrongMomentsNamed = 0.8;

// Issue 31 item 1's bars, on the withheld seeds: rotors named in >= 90 % of rotor sessions,
// |h| within 10 % and its direction within 10°; no rotor named in a look-alike session
// (the stopped wheel among them: wrong moments alone, on every body).
TEST_CASE("rotor sessions are named a rotor, look-alike sessions never", "[rotor][sessions]") {
  namespace gen = aloft::generator;
  std::map<std::string, KindTally> tallies;
  for (const gen::SessionCase& c : gen::rotor_session_cases(rotor_seeds(), sessions_per_kind(), 4)) {
    if (kind_wanted(kind_of(c))) judge_session(c, tallies[kind_of(c)]);
  }
  int rotor_sessions = 0, rotor_named = 0, h_right = 0, look_alikes_named = 0;
  for (const auto& [kind, t] : tallies) {
    std::printf(
        "%-14s sessions naming a rotor %d of %d (confident %d; |h| within 10 %% and 10 deg on %d; tensor "
        "intervals hold the truth on %d, ratios within 1 %% on %d, of %d); flights listing a rotor %d of "
        "%d\n",
        kind.c_str(), t.named, t.sessions, t.confident, t.h_right, t.tensors_covered, t.tensors_close,
        t.tensors, t.flights_listed, t.flights);
    if (kind == "rotor_moments") {
      CHECK(t.named >= kRotorWithWrongMomentsNamed * t.sessions);
      CHECK(t.h_right == t.named);  // a rotor named beside wrong moments has the right h
      // The moments read from the pair's fit, not from the moments alone, which the rotor
      // pulls off (tensor_intervals.cpp, moments_fit). Measured: ratios within 0.01 % of the
      // truth, every interval holding it; read from the moments alone, 1.8 to 8.4 % off and
      // one interval of five missing it.
      CHECK(t.tensors_covered >= kRotorWithWrongMomentsNamed * t.tensors);
      CHECK(t.tensors_close == t.tensors);
    } else if (kind == "large_rotor_moments") {
      // A larger rotor (15-40 % of |L|) with wrong moments (docs/diagnose.md, "Its start"):
      // with the pair's and each flight's fit also started from h read off the readings,
      // 5 of 5 named on the tuning seeds, 4 of 5 on the withheld ones and 5 of 5 on the
      // fresh ones (before: 5, 0 and 4); the withheld miss is the racquet, whose flights'
      // own fits, each at its minimum, scatter 4.1 against a bar of 3. A rotor it names
      // has the right h and the moments read beside it the right ratios.
      CHECK(t.named >= kLargeRotorWithWrongMomentsNamed * t.sessions);
      CHECK(t.h_right == t.named);
      CHECK(t.tensors_close == t.tensors);
    } else if (t.rotor) {
      rotor_sessions += t.sessions;
      rotor_named += t.named;
      h_right += t.h_right;
      // A rotor alone: the moments read beside it (tensor_intervals.cpp). Measured: within
      // 0.07 % of the true ratios; read alone, 0.05 to 98 % off.
      CHECK(t.tensors_close == t.tensors);
      // Named alone, with no second effect taking up a fit stopped in another minimum.
      // Measured on large rotors (40-100 % of |L|): 5 of 5 on each seed set with the start
      // read off the readings (internal_momentum's start_from_readings); from zero alone,
      // 2 of 5 named at all on the tuning seeds (none, inertia_axes, internal_damping with a
      // misalignment), and 3 of 5 with a spurious second effect on the withheld ones.
      if (kind == "large_rotor") CHECK(t.alone == t.sessions);
    } else {
      look_alikes_named += t.named;
    }
  }
  CHECK(rotor_named >= 0.9 * rotor_sessions);
  CHECK(h_right >= 0.9 * rotor_sessions);
  CHECK(look_alikes_named == 0);
}
