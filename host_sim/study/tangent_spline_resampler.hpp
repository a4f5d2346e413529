// Resampling of a pose sequence (e.g. 250 Hz motion capture) to a higher rate (1 kHz in
// the seed study), with the body angular velocity of the interpolating curve.
//
// Method: a C1 cubic Hermite spline in the tangent space of SO(3). On the interval
// [t_k, t_{k+1}] the orientation is q(t) = q_k exp(p(t)), p a cubic in R³ with
// p(t_k) = 0, p(t_{k+1}) = log(q_k^-1 q_{k+1}), and end slopes set from the body rates
// at the two knots. The body rate at knot i is the derivative at t_i of the parabola
// through log(q_i^-1 q_{i-1}), 0, log(q_i^-1 q_{i+1}) (one-sided at the ends), the
// tangent-space form of the Catmull-Rom / three-point derivative; it is carried into
// the chart of q_k through the inverse right Jacobian of SO(3), so the curve passes
// through every pose and its angular velocity is continuous at the knots.
// Along the curve omega_body(t) = J_r(p) dp/dt. A rotation at constant body rate is
// reproduced exactly. Why this and not per-angle splines of Cardan angles (OpenSim's
// route): Cardan angles have a singularity that a tumbling throw may cross; the
// tangent-space spline has none and works for any rotation.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace aloft::host {

struct ResampledPoses {
  std::vector<double> time_s;
  std::vector<Eigen::Quaterniond> orientation;
  std::vector<Eigen::Vector3d> omega_body;  // rate of the interpolating curve
};

// Right Jacobian of SO(3) and its inverse: exp(p + d) ≈ exp(p) exp(J_r(p) d).
Eigen::Matrix3d so3_right_jacobian(const Eigen::Vector3d& p);
Eigen::Matrix3d so3_right_jacobian_inverse(const Eigen::Vector3d& p);

// Resamples poses given at strictly increasing times (at least 3) onto t_0 + i/rate_hz
// for every such time up to the last pose (plus rounding of 1e-9 s). Throws
// std::invalid_argument on fewer than 3 poses or non-increasing times.
ResampledPoses resample_poses(const std::vector<double>& time_s,
                              const std::vector<Eigen::Quaterniond>& orientation, double rate_hz);

}  // namespace aloft::host
