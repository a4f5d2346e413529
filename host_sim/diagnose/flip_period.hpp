// The flip period of a throw about the intermediate axis, measured and predicted, as the
// racquet study (fbubbar/sci1-t2, UBC 2025) reports it: the period of the rate about the
// intermediate principal axis by their "point method" (zero crossings and local extrema
// of that component are quarter periods apart; period = 4 x their mean spacing), and the
// simulation started from the flight's first sample. Predicting it with the nominal model
// and with the diagnosed effect shows what the diagnosis buys a user.
#pragma once

#include <optional>
#include <vector>

#include "diagnose/flight.hpp"
#include "diagnose/flight_model.hpp"

namespace aloft::host::diagnose {

// 4 x the mean spacing of zero crossings and local extrema (over 5 samples) of `value`;
// none with fewer than two such events.
std::optional<double> point_method_period(const std::vector<double>& time_s,
                                          const std::vector<double>& value);

struct FlipPeriod {
  double measured_s = 0.0;
  double nominal_s = 0.0;  // nominal model from the first sample
  std::optional<double> diagnosed_s;  // with the diagnosed effect (when one applies)
  double nominal_error() const { return std::abs(nominal_s - measured_s) / measured_s; }
};

// Measured and predicted periods of `flight` (none if a period cannot be measured in the
// data or the predictions). `diagnosed` (optional) is the effect model and parameters to
// predict with besides the nominal one.
std::optional<FlipPeriod> flip_period(const Flight& flight, const NominalInertia& nominal,
                                      const EffectModel* diagnosed, const Eigen::VectorXd& theta);

}  // namespace aloft::host::diagnose
