#include "diagnose/5_flow/folds_within_flight.hpp"

#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/2_model/flight_model.hpp"
#include "diagnose/3_fit/fold_impulse_time.hpp"
#include "diagnose/4_judge/tensor_intervals.hpp"

namespace aloft::host::diagnose {
namespace {

std::vector<Effect> effects_of_model(const Candidate& c) {
  std::vector<Effect> out = c.base;
  if (c.effect != Effect::none) out.push_back(c.effect);
  return out;
}

}  // namespace

void FoldsWithinFlight::judge_held_out(Candidate& c, const JudgedFlights::FoldFit& fit_fold) const {
  GapSums sums;
  c.heldout_readings.push_back(flight_.judge_folds(
      0, nominal_,
      [&](std::size_t f) {
        c.fold_fits.push_back(fit_fold(f));
        return c.fold_fits.back();
      },
      sums));
  set_heldout_gap(c, {sums});
  if (!has_searched_time(model_of(c.fit, nominal_, 0))) return;
  std::vector<char> unseen(flight_.all[0].flight->size(), 0);
  for (std::size_t f = 0; f < c.fold_fits.size(); ++f) {
    const SampleRange gap = unseen_jump_gap(c.fold_fits[f], flight_.train[0][f]);
    for (std::size_t k = gap.first; k < gap.end; ++k) unseen[k] = 1;
  }
  c.unseen_jump = {std::move(unseen)};
}

Candidate FoldsWithinFlight::nominal_model() const {
  Candidate c;
  c.fit = none_full_;
  SharedLinearisation at_solution(none_full_, nominal_, flight_.all[0]);
  judge_held_out(c, [&](std::size_t f) {
    return refit_from_solution(none_full_, nominal_, flight_.train[0][f], 0.0, at_solution.at(0.0));
  });
  return c;
}

Candidate FoldsWithinFlight::evaluate(const Candidate& base, Effect added) const {
  Candidate c;
  c.effect = added;
  c.base = effects_of_model(base);
  c.fit = fit_added_effect(base.fit, added, nominal_, flight_.all);
  c.params = effect_parameters(model_of(c.fit, nominal_, 0), c.fit.theta);
  // A smooth model's fold fit is one Gauss-Newton step from the all-data solution
  // (refit_from_solution). An added impulse's time is searched again on each fold
  // (fold_impulse_time.hpp: the lower training cost of the search and the all-data
  // solution moved onto the fold, the jump in the middle of a gap the fold does not see).
  // An impulse of the base keeps the time its own fold found; where that is not the
  // all-data time, the all-data solution is no near start (practice2/A02's second step
  // held out 0.07-0.08 by one step where the refit reached 0.03), so the fold is refitted.
  const bool searched = describe(added).searched_parameters > 0;
  // The folds' steps from the all-data solution share its Jacobian (one, not two).
  SharedLinearisation at_solution(c.fit, nominal_, flight_.all[0]);
  judge_held_out(c, [&](std::size_t f) {
    const FlightData& train = flight_.train[0][f];
    const double fold_time = base.fold_fits[f].flights[0].impulse_time_s;
    if (searched) {
      return fold_impulse_fit(fit_added_effect(base.fold_fits[f], added, nominal_, {train}, &c.fit.theta),
                              c.fit, nominal_, train, &at_solution);
    }
    if (fold_time != c.fit.flights[0].impulse_time_s) {
      return fit_added_effect(base.fold_fits[f], added, nominal_, {train}, &c.fit.theta);
    }
    return refit_from_solution(c.fit, nominal_, train, fold_time, at_solution.at(fold_time));
  });
  // The folds are fitted: the Jacobians need not outlive them (a few hundred kB each).
  c.fit.linearisation.reset();
  for (EffectFit& fold : c.fold_fits) fold.linearisation.reset();
  return c;
}

bool FoldsWithinFlight::tensor_report(const Analysis& analysis, TensorReport& report) const {
  return flight_tensor_report(analysis, flight_.flights, nominal_, report);
}

}  // namespace aloft::host::diagnose
