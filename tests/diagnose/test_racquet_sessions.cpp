// The real racquet sessions of ../shared/data/real/racquet (phyphox gyro at 100 Hz on a
// thrown tennis racquet): the pooled compound verdict, its leave-one-flight-out shrink,
// what drag and a gyro bias add, and the flip period predicted from the first sample and
// from each flight's fitted initial state (flip_period.hpp), nominal and with the pooled
// model fitted without the flight. The assertions pin the findings docs/validation/diagnose-accuracy.md
// reports (its racquet table), so a change that overturns them is noticed; where issue 8's bars are not met
// the assertions say what is found instead.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

#include "common/body_file.hpp"
#include "diagnose/4_judge/between_flight_scatter.hpp"
#include "diagnose/4_judge/tensor_intervals.hpp"
#include "diagnose/5_flow/diagnosis.hpp"
#include "diagnose/1_input/flight_input.hpp"
#include "diagnose/6_report/report_text.hpp"
#include "readers/imu_csv_reader.hpp"
#include "readers/segments.hpp"

namespace fs = std::filesystem;
using namespace aloft::host;
using namespace aloft::host::diagnose;

namespace {

// The candidate for `added` at the second step of the stepwise selection (what it adds to
// the first effect), or nullptr.
const Candidate* second_step(const Analysis& a, Effect added) {
  if (a.steps.size() < 2) return nullptr;
  for (const Candidate& c : a.steps[1].candidates) {
    if (c.effect == added && !c.reference && c.evaluated) return &c;
  }
  return nullptr;
}

void print_session(const char* session, const SessionDiagnosis& d) {
  std::printf("== %s\n%s", session, session_summary(d).c_str());
  for (std::size_t i = 0; i < d.pooled.steps.size(); ++i) {
    const ModelStep& s = d.pooled.steps[i];
    const std::vector<Candidate>& candidates = i == 0 ? d.pooled.candidates : s.candidates;
    for (const Candidate& c : candidates) {
      if (c.evaluated && !c.reference && c.effect != Effect::none) {
        std::printf("   step %zu + %-20s held-out rel err %.4f -> %.4f (shrink %6.3f)\n", i + 1,
                    effect_name(c.effect), s.heldout_rms_rel_err_before, c.heldout_rms_rel_err, c.shrink);
      }
    }
  }
  for (const FlightDiagnosis& f : d.flights) {
    if (!f.flip_period) continue;
    const FlipPeriod& p = *f.flip_period;
    std::printf("   flight %s (%s): period %.3f s measured; first sample %.3f nominal", f.name.c_str(),
                f.comment.c_str(), p.measured_s, p.nominal_s);
    if (p.diagnosed_s) std::printf(", %.3f diagnosed", *p.diagnosed_s);
    if (p.nominal_fitted_s) std::printf("; fitted start %.3f nominal", *p.nominal_fitted_s);
    if (p.diagnosed_fitted_s) std::printf(", %.3f diagnosed", *p.diagnosed_fitted_s);
    std::printf("\n");
  }
}

bool in(const std::vector<Effect>& list, Effect e) {
  return std::find(list.begin(), list.end(), e) != list.end();
}

SessionDiagnosis diagnose_named(const fs::path& root, const char* session, const Body& body,
                                std::vector<Flight>& flights) {
  const ImuLog log = read_imu_csv((root / session / "gyro.csv").string());
  flights = flights_from_segments(log, body, read_segments_csv((root / session / "segments.csv").string()));
  SessionDiagnosis d = diagnose_session(flights, NominalInertia::of(body.inertia), 2);
  print_session(session, d);
  return d;
}

// The flights' own fits of `effect` compared as the session's note compares them, plainly
// (between_flight_scatter) and allowing for each flight's serially correlated misfit
// (between_flight_scatter_serial). {plain, serial}; -1 where not measured.
std::pair<double, double> own_fits_scatter(const SessionDiagnosis& d, Effect effect) {
  std::vector<const Analysis*> own;
  std::vector<const Flight*> of;
  for (std::size_t j = 0; j < d.flights.size(); ++j) {
    own.push_back(&d.flights[j].analysis);
    of.push_back(d.flights[j].flight);
  }
  const auto plain = between_flight_scatter(effect, own),
             serial = between_flight_scatter_serial(effect, own, of);
  return {plain ? plain->chi_square_per_dof : -1.0, serial ? serial->chi_square_per_dof : -1.0};
}

// The racquet test below, both sessions:
void check_flights_agree(const SessionDiagnosis& first, const SessionDiagnosis& second) {
  // Do the flights truly disagree? Their own fits' residuals are nearly all serially
  // correlated (lag-1 rho of the own moments fit 0.87-0.95, at the clamp in 9 of 11
  // flights): the model's miss is a slow motion, not noise. Allowing for that, the
  // moments and the gyro scale the flights fit on their own agree (scatter below 1, where
  // the plain comparison reads 10-21); their gyro biases still disagree in the first
  // session. The session's note says both, and that the flights agree.
  for (const SessionDiagnosis* session : {&first, &second}) {
    for (Effect e : {Effect::inertia_moments, Effect::gyro_scale, Effect::gyro_bias}) {
      const auto [plain, widened] = own_fits_scatter(*session, e);
      std::printf(
          "   flights' own %-16s scatter %8.2f, widened for the residuals' serial correlation %6.2f\n",
          effect_name(e), plain, widened);
      if (e != Effect::gyro_bias) {
        CHECK(plain > 3.0);
        CHECK(widened > 0.0);
        CHECK(widened < 1.0);
      }
    }
    int scatter_notes = 0;
    for (const Note& note : session->pooled.notes) {
      if (note.text.find("beyond their own uncertainty") == std::string::npos) continue;
      ++scatter_notes;
      CHECK(note.text.find("so the flights agree on it") != std::string::npos);
    }
    CHECK(scatter_notes == 1);
  }
  CHECK(own_fits_scatter(first, Effect::gyro_bias).second > 3.0);
}

}  // namespace

TEST_CASE("racquet sessions: compound verdict, held-out shrink, drag and bias, flip periods", "[racquet]") {
  const fs::path root = fs::path(ALOFT_SHARED_DIR) / "data" / "real" / "racquet";
  if (!fs::exists(root / "body.json")) {
    WARN("skipped: " << root.string() << " is absent (../shared not beside the checkout)");
    return;
  }
  const Body body = read_body_file((root / "body.json").string());
  std::vector<Flight> first_flights, second_flights;
  const SessionDiagnosis first = diagnose_named(root, "2025-01-16_17-10-11", body, first_flights);
  const SessionDiagnosis second = diagnose_named(root, "2025-01-23_18-29-01", body, second_flights);

  for (const SessionDiagnosis* d : {&first, &second}) {
    const Analysis& a = d->pooled;
    // The nominal model misses the measured motion by far more than the phone's noise.
    CHECK(a.where.gap_over_noise > 100.0);
    // Wrong moments, or their gyro-only twin here (a non-uniform gyro scale), come first.
    REQUIRE_FALSE(a.verdict.effects.empty());
    const VerdictEffect& lead = a.verdict.effects.front();
    CHECK((in(lead.equivalent, Effect::inertia_moments) || in(lead.equivalent, Effect::gyro_scale)));
    // Air drag (the authors' explanation of the falling |L|) and a gyro bias add little
    // to the moments, held out: < 10 % and < 5 %.
    const Candidate* drag = second_step(a, Effect::aero_torque);
    const Candidate* bias = second_step(a, Effect::gyro_bias);
    REQUIRE(drag != nullptr);
    REQUIRE(bias != nullptr);
    CHECK(drag->shrink < 0.10);
    CHECK(bias->shrink < 0.05);
    REQUIRE(d->flip_period);
    CHECK(d->flip_period->flights >= 3);
    // The nominal model's flip-period error from the first sample is of the authors'
    // size (about 17 %).
    CHECK(d->flip_period->mean_error_nominal > 0.10);
    CHECK(d->flip_period->mean_error_nominal < 0.25);
  }

  // 2025-01-16: the moments and an energy loss (the rotor of internal_damping) join;
  // together they take more than half of the held-out gap (issue 8: >= 40 %).
  const Verdict& v1 = first.pooled.verdict;
  REQUIRE(v1.effects.size() == 2);
  CHECK(v1.effects[1].effect == Effect::internal_damping);
  CHECK(1.0 - v1.heldout_rms_rel_err_after / v1.heldout_rms_rel_err_before > 0.50);
  // Flip period: from each flight's fitted start the pooled model is within 5 % (and the
  // nominal one within 3 %); from the first sample it halves the nominal error but
  // stays above 5 %.
  const FlipPeriodSummary& p1 = *first.flip_period;
  CHECK(p1.fitted_flights == 3);
  CHECK(p1.mean_error_diagnosed_fitted < 0.05);
  CHECK(p1.mean_error_nominal_fitted < 0.03);
  CHECK(p1.mean_error_diagnosed < 0.5 * p1.mean_error_nominal);
  CHECK(p1.mean_error_diagnosed > 0.05);

  // 2025-01-23: one effect, and it takes under 40 % of the held-out gap (the bar is not
  // met); the flip period is no better than nominal by either definition.
  const Verdict& v2 = second.pooled.verdict;
  CHECK(v2.effects.size() == 1);
  const double shrink2 = 1.0 - v2.heldout_rms_rel_err_after / v2.heldout_rms_rel_err_before;
  CHECK(shrink2 > 0.25);
  CHECK(shrink2 < 0.40);
  const FlipPeriodSummary& p2 = *second.flip_period;
  CHECK(p2.mean_error_diagnosed > 0.10);
  CHECK(p2.mean_error_diagnosed_fitted > 0.10);

  check_flights_agree(first, second);
}
