// A torque-free flight sampled at a fixed rate, in float or double, with either of the
// core's integrators: what `aloft simulate` writes and what the tests compare with the
// exact solutions.
#pragma once

#include <string>
#include <vector>

#include "aloft/dynamics/inertia_tensor.hpp"
#include "aloft/dynamics/rigid_body_state.hpp"

namespace aloft::host {

enum class IntegratorKind { rk4, splitting };
enum class Precision { double_precision, single_precision };

struct TrajectoryRequest {
  RigidBodyState<double> initial;
  double duration_s = 1.0;
  double rate_hz = 1000.0;
  // Longest internal step: samples further apart are reached in equal sub-steps.
  double max_step_s = 1e-3;
  IntegratorKind integrator = IntegratorKind::rk4;
  Precision precision = Precision::double_precision;
};

struct TrajectorySample {
  double t_s;
  RigidBodyState<double> state;
};

// One sample per 1/rate from t = 0 to duration inclusive. Throws aloft::host::Error on a
// request the core refuses (the message carries the core's status).
std::vector<TrajectorySample> simulate_trajectory(const InertiaTensor<double>& inertia,
                                                  const TrajectoryRequest& request);

IntegratorKind integrator_from_name(const std::string& name);  // "rk4" | "splitting"

// The request `aloft simulate` makes: omega in body axes (rad/s), the orientation q0
// (w, x, y, z), refused unless of unit length and then normalised, the duration (s), the
// rate (Hz), the integrator by name and the precision. Throws Error as the command does.
TrajectoryRequest simulate_request(const Eigen::Vector3d& w0, const Eigen::Vector4d& q0_wxyz,
                                   double duration_s, double rate_hz, const std::string& integrator,
                                   bool single_precision);

}  // namespace aloft::host
