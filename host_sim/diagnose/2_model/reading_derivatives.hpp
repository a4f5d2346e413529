// The readings' derivatives along the theta directions that need no simulation: the
// sensor's (bias, scale, rotation), read through the sensor alone, and the impulse's jump,
// carried by the flow map of the rate columns. The fitter's Jacobian takes them in place
// of differenced columns (3_fit/flight_jacobian.cpp).
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/effect_model.hpp"

namespace aloft::host::diagnose {

// The theta directions (1: yes) along which only the sensor's terms move (bias, scale,
// rotation): the readings' derivatives along them need no simulation.
std::vector<char> sensor_directions(const EffectModel& model, const Eigen::VectorXd& theta);

// d readings / d theta_i for each direction i that `directions` marks (from
// sensor_directions), from `readings`, the prediction at theta: the reading is
// scale (R w) + bias, so the rate w behind each reading is differentiated through the
// sensor alone. `columns`: 3n rows (sample k at 3k) and a column per theta entry at
// least, sized by the caller (the fitter's Jacobian): each marked column is written, the
// others are left as they are (no matrix of every theta column zeroed: case00
// 407.1 -> 405.0 M instructions).
void sensor_reading_derivatives(const EffectModel& model, const Flight& flight, const Eigen::VectorXd& theta,
                                const std::vector<Eigen::Vector3d>& readings,
                                const std::vector<char>& directions, Eigen::MatrixXd& columns);

// The theta directions (1: yes) along which only the impulse's jump moves.
std::vector<char> impulse_directions(const EffectModel& model, const Eigen::VectorXd& theta);

// d readings / d theta_i for each impulse direction i that `directions` marks, without
// simulating: beyond the impulse (on the far side from `ref`), a change of the jump is a
// change of the rate where the walk met it, carried on by the same flow map as a change
// of omega_ref. `jacobian`: 3n rows (in any weighting: the result has the same), one
// column per theta entry and then d readings / d omega_ref, three; `impulse_rate_derivative`:
// d rate_at_impulse / d omega_ref (predict_readings). Each marked theta column is written
// in place (zero on the near side), the others are left as they are: the fitter's
// Jacobian takes them as they come, with no matrix of every theta column zeroed and then
// copied (case00 421.3 -> 409.0 M instructions).
void impulse_reading_derivatives(const EffectModel& model, const Flight& flight, std::size_t ref,
                                 const Eigen::VectorXd& theta, const Eigen::Matrix3d& impulse_rate_derivative,
                                 const std::vector<char>& directions, Eigen::MatrixXd& jacobian);

}  // namespace aloft::host::diagnose
