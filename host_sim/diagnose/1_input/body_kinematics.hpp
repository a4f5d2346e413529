// Each sample of a gyro and accelerometer series in body axes, with w_dot from the gyro:
// what aloft/dynamics/free_flight_residual.hpp takes to give the specific force at the centre of
// mass, |a - K(w, w_dot) r| (the hand's, the ground's or a blow's force per unit mass).
// The diagnosis reads it where the firmware's code is not run over the data: inside a cut
// (contact.hpp) and at a fitted impulse (4_judge/impulse_force_check.hpp).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

#include "aloft/dynamics/free_flight_residual.hpp"

namespace aloft::host::diagnose {

// w_dot from the gyro about this far either side. The firmware takes 1 ms
// (StreamClockSettings::derivative_half_span_us); 2 ms here keeps a 4 kHz gyro's
// differenced noise (0.05 rad/s per sample) below 1 m/s² of |K r| for r up to 5 cm.
constexpr double kDerivativeHalfSpan_s = 0.002;

// Sample k of the series (sensor axes in, body axes out through the rotation matrix
// sensor_to_body). time_s strictly increasing.
BodyKinematics<double> body_kinematics_at(const std::vector<double>& time_s,
                                          const std::vector<Eigen::Vector3d>& gyro_rad_s,
                                          const std::vector<Eigen::Vector3d>& accel_m_s2,
                                          const Eigen::Matrix3d& sensor_to_body, std::size_t k);

}  // namespace aloft::host::diagnose
