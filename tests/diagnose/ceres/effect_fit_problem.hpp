// One effect's fit to one or more flights, as an ArrowProblem that any fitter can take:
// the problem fit_effect (diagnose/3_fit/effect_fit.cpp) hands to minimise, rebuilt from
// the public model so that the hand-written fitter and Ceres can be given the same one
// (fitter_comparison_benchmark.cpp). Residuals (predicted - measured) / sigma on every
// usable sample, the flight's noise floor as sigma, the effect's reference sample; the
// start is fit_effect's: theta at zero (an effect with no neutral theta, internal
// damping, at its descriptor's joining rotor), each flight's rate from the nominal fit.
//
// Two differences from fit_effect, both the same for either fitter: the Jacobian is
// forward differences in every column (fit_effect reads the sensor's columns, gyro_bias'
// for one, off the prediction), and a searched start (internal damping's grid) is
// replaced by the one joining start.
#pragma once

#include <atomic>
#include <memory>
#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/effect.hpp"
#include "diagnose/2_model/flight_model.hpp"
#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/3_fit/effect_fit.hpp"
#include "diagnose/3_fit/flight_data.hpp"
#include "diagnose/3_fit/levenberg_marquardt.hpp"

namespace aloft::host::diagnose {

struct EffectFitProblem {
  std::vector<Flight> flights;
  EffectModel model;
  std::vector<FlightData> data;
  std::vector<std::size_t> refs;
  EffectFit nominal_fit;  // the `none` fit of the same data, whence the starting rates
  ArrowProblem problem;   // its residuals count each call in `simulations`
  Eigen::VectorXd theta_start;
  std::vector<Eigen::VectorXd> rates_start;
  // Predictions made through `problem` (one a residual evaluation of one flight, one a
  // differenced column): what a fit costs here.
  mutable std::atomic<long> simulations{0};
};

// `effect` fitted to all of `flights` at once (a pooled fit when there are several).
// Held by pointer: `problem` refers to the rest.
std::unique_ptr<EffectFitProblem> effect_fit_problem(Effect effect, std::vector<Flight> flights,
                                                     const NominalInertia& nominal);

}  // namespace aloft::host::diagnose
