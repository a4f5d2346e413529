// The Jacobian of one flight's residuals in a fit (fit_problem.hpp), with the columns that
// need no simulation taken from the model's derivatives and the rest differenced as the
// fitter would. Inside the fitter only.
#pragma once

#include <Eigen/Core>

#include "diagnose/3_fit/fit_setup.hpp"

namespace aloft::host::diagnose {

// The residuals of one flight and their Jacobian [theta | omega_ref] when some theta
// directions need no simulation: the sensor's (sensor_reading_derivatives) and the
// impulse's (impulse_reading_derivatives, from the rate columns); or when two rate
// columns can be differenced side by side (predict_readings_pair: a model whose
// reference is the release sample, the rotor's, has one walk a prediction; case00
// 437.5 -> 424.6 M instructions). Every other column is differenced exactly as the fitter
// would (same step, same residuals). False when none of these holds: the fitter then
// differences every column itself. `r`: on entry the residuals when known, else empty.
// `rate_derivative` (optional): where the rate columns' change of the rate at the impulse
// goes (impulse_reading_derivatives), when the model has one.
bool flight_jacobian(const FitSetup& setup, int block, const Eigen::VectorXd& theta,
                     const Eigen::VectorXd& local, Eigen::VectorXd& r, Eigen::MatrixXd& jacobian,
                     Eigen::Matrix3d* rate_derivative = nullptr);

}  // namespace aloft::host::diagnose
