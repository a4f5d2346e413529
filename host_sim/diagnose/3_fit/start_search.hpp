// The fits whose start is searched, not taken: the impulse's time, which is not a smooth
// parameter, searched over the flight; and an effect's start grid (descriptor
// `start_grid`: the damping rotor's), each start costed and the best refined. Each keeps
// the lower of two refined minima and records the other (OtherMinimum). Inside the fitter
// only.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/3_fit/effect_fit_result.hpp"
#include "diagnose/3_fit/fit_setup.hpp"
#include "diagnose/3_fit/levenberg_marquardt.hpp"

namespace aloft::host::diagnose {

// An effect that acts at one instant (descriptor `searched_parameters`: the impulse): its
// time is searched over the flight, the rest fitted at each time tried.
EffectFit fit_with_time_search(FitSetup& setup, const EffectFit* nominal_fit);

// An effect with a start grid fitted from no seed: `problem` (problem_of(setup, p)) from
// the grid's starts, `rates` the flights' starting rates (starting_rates at zero).
EffectFit fit_from_start_grid(FitSetup& setup, const ArrowProblem& problem, const StartGrid& grid,
                              const std::vector<Eigen::VectorXd>& rates, int p);

}  // namespace aloft::host::diagnose
