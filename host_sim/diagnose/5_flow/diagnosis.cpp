#include "diagnose/5_flow/diagnosis.hpp"

#include <algorithm>
#include <cmath>

#include "diagnose/3_fit/held_out.hpp"
#include "diagnose/4_judge/baseline_gap.hpp"
#include "diagnose/4_judge/candidate_ranking.hpp"
#include "diagnose/4_judge/impulse_force_check.hpp"
#include "diagnose/4_judge/onset.hpp"
#include "diagnose/4_judge/spin_up_end.hpp"
#include "diagnose/5_flow/folds_within_flight.hpp"
#include "diagnose/5_flow/judge_candidates.hpp"
#include "diagnose/5_flow/judged_flights.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

// The flight's identity and sampling, before any judging.
FlightDiagnosis describe_flight(const Flight& flight) {
  FlightDiagnosis d;
  d.name = flight.name;
  d.comment = flight.comment;
  d.flight = &flight;
  d.start_s = flight.start_s();
  d.end_s = flight.end_s();
  d.samples = flight.size();
  d.rate_hz = flight.rate_hz();
  d.gaps = time_gaps(flight.time_s);
  d.unusable_samples = static_cast<std::size_t>(std::count(flight.usable.begin(), flight.usable.end(), 0));
  return d;
}

// The nominal model's gap over the whole flight: baseline, slices and invariants.
void describe_baseline(Analysis& analysis, const Flight& flight, const NominalInertia& nominal,
                       const NoiseFloor& noise, const EffectFit& none_full) {
  const Vec3 inverse_sigma = noise.sigma.cwiseInverse();
  std::vector<Vec3> readings;
  predict(none_full, nominal, 0, flight, readings);
  BaselineGap baseline;
  baseline.add(flight, readings, inverse_sigma);
  baseline.describe(analysis);
  describe_slices(flight, readings, inverse_sigma, analysis.where);
  analysis.where.invariants = measured_invariants(flight, nominal, noise);
}

// Onset: for an impulse, the fitted time; otherwise when the nominal motion fitted to
// the first fifth of the flight stops explaining the data. None when the verdict is none.
void find_onset(Analysis& analysis, const Flight& flight, const NominalInertia& nominal,
                const EffectFit& none_full, const Vec3& inverse_sigma) {
  const EffectModel final_model = model_of(analysis.model.fit, nominal, 0);
  if (has_searched_time(final_model)) {
    analysis.where.onset_s = final_model.impulse_time_s;
  } else if (analysis.verdict.effect != Effect::none) {
    const FlightData lead{&flight, leading_samples(flight.size(), 0.2, kMinimumSamples), inverse_sigma};
    const EffectFit early = fit_effect(Effect::none, nominal, {lead}, &none_full);
    std::vector<Vec3> readings;
    predict(early, nominal, 0, flight, readings);
    analysis.where.onset_s = cusum_onset(flight, readings, inverse_sigma);
    if (!analysis.where.onset_s) analysis.where.onset_s = flight.start_s();
  }
}

}  // namespace

FlightDiagnosis diagnose_flight(Flight& flight, const NominalInertia& nominal) {
  FlightDiagnosis d = describe_flight(flight);
  Analysis& analysis = d.analysis;
  const std::size_t usable = flight.size() - d.unusable_samples;
  if (usable < kMinimumSamples) {
    analysis.verdict.confident = false;
    analysis.verdict.could_not_judge.push_back(
        "only " + std::to_string(usable) + " usable samples (at least " + std::to_string(kMinimumSamples) +
        " are needed to fit an initial rate and an effect)");
    analysis.where.dominant_axis = "x";
    return d;
  }
  d.noise = estimate_noise_floor(flight);
  flight.gyro_filter_bend_s2 = d.noise.low_pass_bend_s2;
  analysis.where.noise_floor = d.noise.sigma;
  analysis.where.noise_correlation = d.noise.correlation;
  const Vec3 inverse_sigma = d.noise.weighting_sigma().cwiseInverse();
  JudgedFlights judged;
  judged.add(flight, inverse_sigma);
  const EffectFit none_full = fit_effect(Effect::none, nominal, judged.all, nullptr);
  describe_baseline(analysis, flight, nominal, d.noise, none_full);
  judge_candidates(analysis, judged.ranking_context(nominal, d.noise.resolution),
                   FoldsWithinFlight(judged, nominal, none_full));
  set_spin_up_end(analysis, {&flight});
  check_impulse_against_accelerometer(analysis, flight);
  find_onset(analysis, flight, nominal, none_full, inverse_sigma);
  if (!d.noise.reliable) {
    analysis.verdict.confident = false;
    analysis.verdict.could_not_judge.push_back("too few clean samples to estimate the noise floor");
  }
  return d;
}

}  // namespace aloft::host::diagnose
