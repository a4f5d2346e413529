// The flip period of a throw about the intermediate axis, measured and predicted, as the
// racquet study (fbubbar/sci1-t2, UBC 2025) reports it: the period of the rate about the
// intermediate principal axis by their "point method" (zero crossings and local extrema
// of that component are quarter periods apart; period = 4 x their mean spacing).
//
// Two predictions of it, each with the nominal model and with the diagnosed one:
// - from the first sample (the study's definition): the simulation starts at the first
//   reading taken as the body rate. A phone's first reading after release is low-pass
//   filtered (it still remembers the hand) and noisy, and near the separatrix the period
//   hangs steeply on the start, so this tests the start as much as the model.
// - from the flight's fitted initial state: the model (tensor and effects) is held and
//   only the flight's own rate at its reference sample is fitted to its readings (the
//   same initial-state fit every held-out gap uses, initial_state_fit.hpp). The model
//   never saw the flight when its parameters come from the other flights; the start did
//   see it, so this judges the model, not the start.
#pragma once

#include <optional>
#include <vector>

#include "diagnose/3_fit/effect_fit.hpp"
#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/flight_model.hpp"

namespace aloft::host::diagnose {

// 4 x the mean spacing of zero crossings and local extrema (over 5 samples) of `value`;
// none with fewer than two such events.
std::optional<double> point_method_period(const std::vector<double>& time_s,
                                          const std::vector<double>& value);

struct FlipPeriod {
  double measured_s = 0.0;
  double nominal_s = 0.0;                                      // nominal model from the first sample
  std::optional<double> diagnosed_s;                           // diagnosed model from the first sample
  std::optional<double> nominal_fitted_s, diagnosed_fitted_s;  // from the fitted initial state
  double nominal_error() const { return std::abs(nominal_s - measured_s) / measured_s; }
  double error(double predicted_s) const { return std::abs(predicted_s - measured_s) / measured_s; }
};

// Measured and predicted periods of `flight` (none if a period cannot be measured in the
// data or the nominal prediction). `diagnosed` (optional) is the model and parameters to
// predict with besides the nominal one; `nominal_start` and `diagnosed_start` (optional)
// the flight's fitted initial states under each model.
std::optional<FlipPeriod> flip_period(const Flight& flight, const NominalInertia& nominal,
                                      const EffectModel* diagnosed, const Eigen::VectorXd& theta,
                                      const FlightState* nominal_start = nullptr,
                                      const FlightState* diagnosed_start = nullptr);

}  // namespace aloft::host::diagnose
