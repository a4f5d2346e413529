// A fit of one flight refitted to a fold of its samples by one Gauss-Newton step from its
// solution, sharing the residuals and Jacobian made there between the flight's folds; and
// a pooled fit without each flight in turn, the same way.
#pragma once

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/3_fit/effect_fit_result.hpp"
#include "diagnose/3_fit/flight_data.hpp"

namespace aloft::host::diagnose {

// linearise_at_solution: SolutionLinearisation (effect_fit_result.hpp) made over the samples
// of `data` at the solution of `fit`, the impulse (if the model has one) at `impulse_time_s`.
SolutionLinearisation linearise_at_solution(const EffectFit& fit, const NominalInertia& nominal,
                                            const FlightData& data, double impulse_time_s);

// The fit's own linearisation (EffectFit::linearisation) where it kept one, else
// linearise_at_solution of the fit over `data`, made when a fold first asks for it and
// then kept for the other fold. All three must outlive it.
class SharedLinearisation {
 public:
  SharedLinearisation(const EffectFit& fit, const NominalInertia& nominal, const FlightData& data)
      : fit_(fit), nominal_(nominal), data_(data) {}
  // At the fit's solution with the impulse at `impulse_time_s`: nullptr where it was made
  // for another time already (the fold then makes its own).
  const SolutionLinearisation* at(double impulse_time_s) {
    if (fit_.linearisation != nullptr && fit_.linearisation->impulse_time_s == impulse_time_s) {
      return fit_.linearisation.get();  // the fit's own last iteration made it
    }
    if (!made_) made_ = linearise_at_solution(fit_, nominal_, data_, impulse_time_s);
    return made_->impulse_time_s == impulse_time_s ? &*made_ : nullptr;
  }

 private:
  const EffectFit& fit_;
  const NominalInertia& nominal_;
  const FlightData& data_;
  std::optional<SolutionLinearisation> made_;
};

// `fit`, a fit of one flight to all its samples, refitted to the samples of `data` (a
// fold's training samples) by one Gauss-Newton step from its own solution
// (levenberg_marquardt.hpp, gauss_newton_step), the impulse (if the model has one) at
// `impulse_time_s`. From the all-samples solution that step reaches the fold's own
// solution to first order, so the samples the fold leaves out do not steer its parameters
// to that order: their prediction is still held out. It costs one Jacobian and a
// simulation or two, where a refit from the same start took ten to forty iterations.
//
// `at_solution` (optional): linearise_at_solution of the same fit and impulse time over
// samples that include every one `data` compares; the step then takes its residuals and
// Jacobian from it, with the rows `data` leaves out zeroed, instead of making its own:
// the same numbers bit for bit (see linearise_at_solution).
EffectFit refit_from_solution(const EffectFit& fit, const NominalInertia& nominal, const FlightData& data,
                              double impulse_time_s, const SolutionLinearisation* at_solution = nullptr);

// The effect parameters without each flight in turn (one Gauss-Newton step from `fit`, the
// all-flights solution; levenberg_marquardt.hpp), the flights on up to `threads` threads.
// Not for impulses.
std::vector<Eigen::VectorXd> leave_one_flight_out(const EffectFit& fit, const NominalInertia& nominal,
                                                  const std::vector<FlightData>& data, unsigned threads = 1);
}  // namespace aloft::host::diagnose
