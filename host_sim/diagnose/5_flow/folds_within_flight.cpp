#include "diagnose/5_flow/folds_within_flight.hpp"

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
}

Candidate FoldsWithinFlight::nominal_model() const {
  Candidate c;
  c.fit = none_full_;
  judge_held_out(c, [&](std::size_t f) {
    return fit_effect(Effect::none, nominal_, {flight_.train[0][f]}, &none_full_);
  });
  return c;
}

Candidate FoldsWithinFlight::evaluate(const Candidate& base, Effect added) const {
  Candidate c;
  c.effect = added;
  c.base = effects_of_model(base);
  c.fit = fit_added_effect(base.fit, added, nominal_, flight_.all);
  c.params = effect_parameters(model_of(c.fit, nominal_, 0), c.fit.theta);
  // The fold fit starts from the all-data solution only to save iterations; it then
  // converges on its own training samples.
  judge_held_out(c, [&](std::size_t f) {
    return fit_added_effect(base.fold_fits[f], added, nominal_, {flight_.train[0][f]}, &c.fit.theta);
  });
  return c;
}

bool FoldsWithinFlight::tensor_report(const Analysis& analysis, TensorReport& report) const {
  return flight_tensor_report(analysis, flight_.flights, nominal_, report);
}

}  // namespace aloft::host::diagnose
