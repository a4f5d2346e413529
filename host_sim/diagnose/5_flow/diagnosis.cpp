#include "diagnose/5_flow/diagnosis.hpp"

#include <algorithm>
#include <cmath>

#include "diagnose/3_fit/held_out.hpp"
#include "diagnose/4_judge/baseline_gap.hpp"
#include "diagnose/4_judge/candidate_ranking.hpp"
#include "diagnose/4_judge/plausibility.hpp"
#include "diagnose/4_judge/stepwise_selection.hpp"
#include "diagnose/4_judge/tensor_intervals.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

// The onset detector: a one-sided CUSUM of the per-sample chi-square excess
// (|residual/sigma|^2/3 - 1, mean 0 under noise) with drift 0.5 and alarm at 15; the
// onset is the last time the sum was at zero before the alarm. Under noise alone its
// average run length is far beyond any flight.
std::optional<double> cusum_onset(const Flight& flight, const std::vector<Vec3>& readings,
                                  const Vec3& inverse_sigma) {
  constexpr double kDrift = 0.5, kAlarm = 15.0;
  double sum = 0.0;
  std::size_t start = 0;
  for (std::size_t k = 0; k < flight.size(); ++k) {
    if (!flight.usable[k]) continue;
    const double excess =
        (readings[k] - flight.omega[k]).cwiseProduct(inverse_sigma).squaredNorm() / 3.0 - 1.0;
    sum = std::max(0.0, sum + excess - kDrift);
    if (sum == 0.0) start = k + 1;
    if (sum > kAlarm) return flight.time_s[std::min(start, flight.size() - 1)];
  }
  return std::nullopt;
}

// The baseline gap in ten slices of the flight's time: where along the flight it grows.
void describe_slices(const Flight& flight, const std::vector<Vec3>& readings, const Vec3& inverse_sigma,
                     Where& where) {
  constexpr int kSlices = 10;
  std::vector<GapSums> slices(kSlices);
  const double t0 = flight.start_s();
  const double span = std::max(flight.end_s() - t0, 1e-12);
  for (std::size_t k = 0; k < flight.size(); ++k) {
    if (!flight.usable[k]) continue;
    const int s = std::min(kSlices - 1, static_cast<int>((flight.time_s[k] - t0) / span * kSlices));
    slices[static_cast<std::size_t>(s)].add(readings[k], flight.omega[k], inverse_sigma);
  }
  for (int s = 0; s < kSlices; ++s) {
    TimeSlice slice;
    slice.from_s = t0 + span * s / kSlices;
    slice.to_s = t0 + span * (s + 1) / kSlices;
    slice.rms_da_deg = slices[static_cast<std::size_t>(s)].rms_da_deg();
    slice.rms_rel_err = slices[static_cast<std::size_t>(s)].rms_rel_err();
    where.slices.push_back(slice);
  }
}

std::vector<Effect> effects_of_model(const Candidate& c) {
  std::vector<Effect> out = c.base;
  if (c.effect != Effect::none) out.push_back(c.effect);
  return out;
}

// The flight's identity and sampling, before any judging.
FlightDiagnosis describe_flight(const Flight& flight) {
  FlightDiagnosis d;
  d.name = flight.name;
  d.comment = flight.comment;
  d.flight = &flight;
  d.start_s = flight.start_s();
  d.end_s = flight.end_s();
  d.samples = flight.size();
  d.rate_hz = flight.size() > 1 ? (flight.size() - 1) / std::max(d.end_s - d.start_s, 1e-12) : 0.0;
  d.gaps = time_gaps(flight.time_s);
  d.unusable_samples = static_cast<std::size_t>(std::count(flight.usable.begin(), flight.usable.end(), 0));
  return d;
}

// The one held-out rule of every model of this flight: fitted on each of two interleaved
// folds, judged on the other.
class FlightJudge {
 public:
  FlightJudge(const Flight& flight, const NominalInertia& nominal, const Vec3& inverse_sigma)
      : flight_(flight),
        nominal_(nominal),
        inverse_sigma_(inverse_sigma),
        n_(flight.size()),
        all_{&flight, all_samples(n_), inverse_sigma},
        folds_(interleaved_folds(n_)) {
    for (int f = 0; f < 2; ++f) train_[f] = FlightData{&flight, folds_.train[f], inverse_sigma};
  }

  const FlightData& all() const { return all_; }

  // Fits `c` on each fold with fit_fold(f), judges it on the other fold, and records the
  // held-out gap.
  template <typename FitFold>
  void judge_held_out(Candidate& c, const FitFold& fit_fold) const {
    std::vector<Vec3> heldout(n_, Vec3::Zero()), fold_readings;
    GapSums sums;
    for (std::size_t f = 0; f < 2; ++f) {
      c.fold_fits.push_back(fit_fold(f));
      predict(c.fold_fits.back(), nominal_, 0, flight_, fold_readings);
      for (std::size_t k = 0; k < n_; ++k) {
        if (!folds_.judge[f][k]) continue;
        heldout[k] = fold_readings[k];
        if (flight_.usable[k]) sums.add(fold_readings[k], flight_.omega[k], inverse_sigma_);
      }
    }
    c.heldout_chi_square = sums.chi_square;
    c.heldout_residuals = sums.residuals;
    c.heldout_rms_da_deg = sums.rms_da_deg();
    c.heldout_rms_rel_err = sums.rms_rel_err();
    c.heldout_readings.push_back(std::move(heldout));
  }

  // The nominal model: the reference every candidate of the first step is judged against.
  Candidate nominal_model(const EffectFit& none_full) const {
    Candidate c;
    c.fit = none_full;
    judge_held_out(
        c, [&](std::size_t f) { return fit_effect(Effect::none, nominal_, {train_[f]}, &none_full); });
    return c;
  }

  // A candidate: `added` fitted with the model of `base` on all the data (its parameters)
  // and on each fold (judged on the other), each fit starting from the base model's.
  Candidate evaluate(const Candidate& base, Effect added) const {
    Candidate c;
    c.effect = added;
    c.base = effects_of_model(base);
    c.fit = fit_added_effect(base.fit, added, nominal_, {all_});
    c.params = effect_parameters(model_of(c.fit, nominal_, 0), c.fit.theta);
    // The fold fit starts from the all-data solution only to save iterations; it then
    // converges on its own training samples.
    judge_held_out(c, [&](std::size_t f) {
      return fit_added_effect(base.fold_fits[f], added, nominal_, {train_[f]}, &c.fit.theta);
    });
    return c;
  }

 private:
  const Flight& flight_;
  const NominalInertia& nominal_;
  Vec3 inverse_sigma_;
  std::size_t n_;
  FlightData all_;
  Folds folds_;
  std::array<FlightData, 2> train_;
};

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
  if (theta_offset(final_model, Effect::impulse) >= 0) {
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

FlightDiagnosis diagnose_flight(const Flight& flight, const NominalInertia& nominal) {
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
  analysis.where.noise_floor = d.noise.sigma;
  const Vec3 inverse_sigma = d.noise.weighting_sigma().cwiseInverse();
  const FlightJudge judge(flight, nominal, inverse_sigma);
  const EffectFit none_full = fit_effect(Effect::none, nominal, {judge.all()}, nullptr);
  describe_baseline(analysis, flight, nominal, d.noise, none_full);

  const CandidateEvaluator evaluate = [&](const Candidate& base, Effect added) {
    return judge.evaluate(base, added);
  };
  const Candidate nominal_model = judge.nominal_model(none_full);
  for (Effect effect : candidate_effects(flight.gyro_input)) {
    analysis.candidates.push_back(effect == Effect::none ? nominal_model : evaluate(nominal_model, effect));
  }

  rule_out_senseless(analysis.candidates);
  const RankingContext context{flight.gyro_input,   {&flight}, {inverse_sigma},   flight.mean_speed(),
                               d.end_s - d.start_s, &nominal,  d.noise.resolution};
  rank_candidates(analysis, context);
  select_stepwise(analysis, context, evaluate);
  attach_flight_tensor_report(analysis, flight, nominal);
  find_onset(analysis, flight, nominal, none_full, inverse_sigma);
  if (!d.noise.reliable) {
    analysis.verdict.confident = false;
    analysis.verdict.could_not_judge.push_back("too few clean samples to estimate the noise floor");
  }
  return d;
}

}  // namespace aloft::host::diagnose
