// Fitting one candidate effect to one or more flights: the effect's parameters (shared by
// every flight given) and each flight's initial rate, by weighted least squares on the
// samples a mask lets through. Residuals are (predicted - measured) / sigma per axis, so
// the cost is a chi-square when sigma is the noise floor.
//
// What a fit gives is effect_fit_result.hpp's. The fitter's other entry points come with
// this header: a fit refitted from its solution (refit_from_solution.hpp) and the
// flights' initial rates refitted with the effect held (initial_rates_fit.hpp).
#pragma once

#include <Eigen/Core>

#include <vector>

#include "diagnose/2_model/effect.hpp"
#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/3_fit/effect_fit_result.hpp"
#include "diagnose/3_fit/flight_data.hpp"
#include "diagnose/3_fit/initial_rates_fit.hpp"
#include "diagnose/3_fit/refit_from_solution.hpp"

namespace aloft::host::diagnose {

// Fits `effect` to `data`. `nominal_fit`, the `none` fit of the same data, gives the
// starting rates (nullptr: start from the readings themselves). An impulse belongs to one
// flight: fitting it to several flights at once is refused (std::invalid_argument).
// `theta_start` (optional) starts the effect parameters elsewhere than at nominal.
// `threads`: the flights of a pooled fit are evaluated on up to this many threads (the
// result is the same whatever the count).
EffectFit fit_effect(Effect effect, const NominalInertia& nominal, const std::vector<FlightData>& data,
                     const EffectFit* nominal_fit, const Eigen::VectorXd* theta_start = nullptr,
                     unsigned threads = 1);

// A second start of fit_added_effect for an added effect with a start read off the
// readings (descriptor `start_from_readings`: a rotor), its lower end kept: which one
// suits depends on what the fit is for.
enum class SecondStart {
  none,
  // A session's pooled fit (5_flow/flights_left_out.cpp), from no seed: also the whole fit
  // again from the base effects at nominal (their parameters zero). A rotor pulls the
  // moments fitted alone far off (log-moment parameters 2.0 and -3.9 on a withheld
  // large_rotor_moments cylinder, where 5-20 % is at most 0.2), and from there the pair
  // stopped at chi2 3.3e7 where from nominal it reaches 1.3e4.
  base_at_nominal,
  // A flight's own fit seeded from a pooled one (`theta_start`): also from the added
  // effect's start read off the readings, its base part from theta_start, where that start
  // costs less than where the seeded fit ended.
  readings_when_seeded,
};

// Fits the effects of `base` (a fit of the same data) with `added` jointly: a compound
// model, the next step of a stepwise selection (stepwise_selection.hpp). The base
// parameters start at their fitted values, the added ones at zero (or `theta_start`, the
// whole compound theta); the rates start at the base fit's. An impulse in the base keeps
// its fitted time; an added impulse is searched about the base model. `threads` as for
// fit_effect. `second`: a second start (SecondStart) where the added effect has one.
EffectFit fit_added_effect(const EffectFit& base, Effect added, const NominalInertia& nominal,
                           const std::vector<FlightData>& data, const Eigen::VectorXd* theta_start = nullptr,
                           unsigned threads = 1, SecondStart second = SecondStart::none);

}  // namespace aloft::host::diagnose
