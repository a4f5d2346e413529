// The diagnosis on flights whose effect it is not told (issue 5): the generator in
// generator/ (an independent code path) throws bodies with one injected effect of
// random magnitude, or none, at fixed seeds; the diagnosis sees only the nominal body and
// the data. Scored here against the generator's truth.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <string>

#include "diagnose/5_flow/diagnosis.hpp"
#include "diagnose/1_input/flight_input.hpp"
#include "generator/flight_generator.hpp"
#include "generator/compound_effect_cases.hpp"
#include "generator/withheld_effect_cases.hpp"
#include "readers/marker_pose_fit.hpp"

using namespace aloft::host;
using namespace aloft::host::diagnose;

namespace {

bool listed(const std::vector<std::string>& list, const std::string& name) {
  for (const auto& e : list) {
    if (e == name) return true;
  }
  return false;
}

Eigen::Vector3d vec(const nlohmann::json& j) {
  return Eigen::Vector3d(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
}

// The parameter checks of issue 5 for a verdict in the right class; empty when they hold.
std::string parameter_problem(const std::string& truth_effect, const nlohmann::json& truth, Effect verdict,
                              const EffectParameters& p) {
  char text[200] = "";
  if (truth_effect == "gyro_bias") {
    const Eigen::Vector3d b = vec(truth["bias_rad_s"]);
    if ((p.vector - b).norm() > 0.2 * b.norm())
      std::snprintf(text, sizeof text, "bias off by %.3f of %.3f rad/s", (p.vector - b).norm(), b.norm());
  } else if (truth_effect == "gyro_scale") {
    const Eigen::Vector3d s = vec(truth["scale_error"]);
    if ((p.vector - s).cwiseAbs().maxCoeff() > 0.01)
      std::snprintf(text, sizeof text, "scale error off by %.4f", (p.vector - s).cwiseAbs().maxCoeff());
  } else if (truth_effect == "clock_drift") {
    const double eps = truth["rate_error"].get<double>();
    const double fitted = verdict == Effect::gyro_scale ? p.vector.mean() : p.rate_error;
    if (std::abs(fitted - eps) > 0.01)
      std::snprintf(text, sizeof text, "rate error %.4f vs %.4f", fitted, eps);
  } else if (truth_effect == "inertia_axes" || truth_effect == "sensor_misalignment") {
    const double angle = truth["angle_deg"].get<double>();
    if (std::abs(p.angle_deg - angle) > 2.0)
      std::snprintf(text, sizeof text, "angle %.2f vs %.2f deg", p.angle_deg, angle);
  } else if (truth_effect == "aero_torque") {
    const double k = truth["k_N_m_s2"].get<double>();
    if (std::abs(p.k_N_m_s2 - k) > 0.25 * k)
      std::snprintf(text, sizeof text, "k %.3g vs %.3g", p.k_N_m_s2, k);
  } else if (truth_effect == "impulse") {
    const double t = truth["time_s"].get<double>();
    if (std::abs(p.time_s - t) > 0.030)
      std::snprintf(text, sizeof text, "impulse at %.3f vs %.3f s", p.time_s, t);
  }
  return text;
}

}  // namespace

TEST_CASE("withheld effects: right class in >= 90 %, none for noise, parameters recovered", "[withheld]") {
  int right = 0, total = 0, noise_flights = 0, noise_right = 0, parameter_failures = 0;
  int flagged = 0;  // right class, but the diagnosis itself says its parameters are not pinned
  int one_effect = 0, confident = 0, confident_right = 0, noise_confident = 0;
  for (const auto& c : aloft::generator::withheld_effect_cases()) {
    const aloft::generator::GeneratedFlight g = aloft::generator::generate_flight(c.spec, c.seed);
    const NominalInertia nominal = NominalInertia::of(g.body.inertia);
    Flight flight = c.spec.data == aloft::generator::DataKind::imu
                        ? flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, c.name)
                        : flight_from_poses(fit_poses(g.markers, g.body), c.name);
    const FlightDiagnosis d = diagnose_flight(flight, nominal);
    const Verdict& v = d.analysis.verdict;
    const std::string verdict = effect_name(v.effect);
    const bool ok = listed(g.truth.equivalent, verdict);
    std::string problem;
    bool identifiable = true;
    if (ok && v.chosen >= 0 && v.effect != Effect::none) {
      const Candidate& chosen = d.analysis.candidates[static_cast<std::size_t>(v.chosen)];
      problem = parameter_problem(g.truth.effect, g.truth.params, v.effect, chosen.params);
      identifiable = chosen.identifiable;
    }
    // A parameter the diagnosis reports as not identifiable (verdict not confident) is
    // not held to the tolerance, but such flights are counted and must stay rare.
    if (!problem.empty() && !identifiable) {
      ++flagged;
      problem += " [reported not identifiable]";
    }
    ++total;
    right += ok;
    // A single effect comes out as one effect (or none).
    one_effect += ok && v.effects.size() <= 1;
    confident += v.confident;
    confident_right += v.confident && ok && v.effects.size() <= 1;
    if (g.truth.effect == "none") {
      ++noise_flights;
      noise_right += ok;
      noise_confident += v.confident;
    }
    parameter_failures += !problem.empty() && identifiable;
    std::string all_effects;
    for (const VerdictEffect& e : v.effects) all_effects += std::string(" ") + effect_name(e.effect);
    std::printf("%-32s %-20s -> %-20s %s %s [%s ] %s\n", c.name.c_str(), g.truth.effect.c_str(),
                verdict.c_str(), ok ? "ok   " : "WRONG", problem.c_str(), all_effects.c_str(),
                v.confident ? "confident" : "");
    if (!ok || !problem.empty()) {  // the ranking behind a miss, to see why
      std::printf("    body %s, %zu samples, noise %.4f\n", g.truth.body.c_str(), flight.size(),
                  d.noise.sigma.mean());
      for (const Candidate& k : d.analysis.candidates) {
        std::printf("    %-20s score %12.1f shrink %6.3f %s\n", effect_name(k.effect), k.score, k.shrink,
                    k.note.c_str());
      }
    }
  }
  std::printf(
      "withheld effects: %d of %d right (%.1f %%); none on %d of %d noise-only flights; "
      "%d parameter misses; %d misses reported as not identifiable\n",
      right, total, 100.0 * right / total, noise_right, noise_flights, parameter_failures, flagged);
  std::printf("single effect named alone: %d of %d (%.1f %%); confident %d, right %d\n", one_effect, total,
              100.0 * one_effect / total, confident, confident_right);
  CHECK(total >= 60);
  CHECK(right >= 0.9 * total);
  // The stepwise selection never adds a second effect to a single-effect flight it names.
  CHECK(one_effect == right);
  CHECK(noise_confident == 0);
  CHECK(confident_right >= 0.95 * confident);
  CHECK(noise_right == noise_flights);
  CHECK(parameter_failures == 0);
  CHECK(flagged <= total / 20);
}

// Compound gaps (issue 8): two effects at once, every pair of different classes; both
// must be named by verdict.effects (each effect's name in the truth's class of one of
// them) on at least 80 % of the flights.
TEST_CASE("compound flights: both effects named on >= 80 %", "[compound]") {
  int both = 0, total = 0, confident = 0, confident_right = 0;
  for (const auto& c : aloft::generator::compound_effect_cases()) {
    const aloft::generator::GeneratedFlight g = aloft::generator::generate_flight(c.spec, c.seed);
    const NominalInertia nominal = NominalInertia::of(g.body.inertia);
    Flight flight = flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, c.name);
    const FlightDiagnosis d = diagnose_flight(flight, nominal);
    const Verdict& v = d.analysis.verdict;
    std::string said;
    int named = 0;
    for (const auto& truth_class : g.truth.equivalents) {
      bool found = false;
      for (const VerdictEffect& e : v.effects) found = found || listed(truth_class, effect_name(e.effect));
      named += found;
    }
    for (const VerdictEffect& e : v.effects) said += std::string(" ") + effect_name(e.effect);
    const bool ok = named == static_cast<int>(g.truth.equivalents.size());
    ++total;
    both += ok;
    confident += v.confident;
    confident_right += v.confident && ok;
    std::printf("%-48s %-8s ->%s %s%s\n", c.name.c_str(), g.truth.body.c_str(), said.c_str(),
                ok ? "ok" : "MISSED", v.confident ? " confident" : "");
  }
  std::printf("compound flights: both named on %d of %d (%.1f %%); confident %d, of which right %d\n", both,
              total, 100.0 * both / total, confident, confident_right);
  CHECK(total == 21);
  CHECK(both >= 0.8 * total);
  CHECK(confident_right >= 0.95 * confident);
}
