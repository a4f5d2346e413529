// One flight as the study analyses it: sampled states to seed simulations from, and the
// measured angular velocity the simulations are compared with, in body axes (SPEC §1)
// and, for pose flights, in world axes (study/da_frame.hpp).
//
// Two kinds:
//  - pose flights (motion capture, pose files, the built-in throw): an orientation at
//    every sample; measured omega_j = log(q_j^-1 q_{j+1}) / (t_{j+1} - t_j) for j < n-1,
//    from "each pair of consecutive rotation matrices" as the seed study puts it (it
//    does not say in which axes; the world-axes omega is q_j omega_j); a simulation is
//    compared the same way, from its own consecutive orientations;
//  - rate flights (IMU): no orientation; measured omega_j is the gyro in body axes at
//    every sample, and a simulation integrates the body rate alone (torque-free body
//    rates do not depend on orientation).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

namespace aloft::host {

struct StudyFlight {
  std::string name;      // e.g. "built-in throw", "segment 3"
  double start_s = 0.0;  // where the flight lies in its source file
  double end_s = 0.0;
  std::vector<double> time_s;                         // n samples, strictly increasing
  std::vector<Eigen::Quaterniond> orientation;        // n for pose flights, empty for rate flights
  std::vector<Eigen::Vector3d> state_omega_body;      // n: omega of the state seeded at sample k
  std::vector<Eigen::Vector3d> measured_omega_body;   // n-1 (pose) or n (rate) comparisons
  std::vector<Eigen::Vector3d> measured_omega_world;  // n-1 (pose: q_j omega_j), empty (rate)

  bool has_orientation() const { return !orientation.empty(); }
  std::size_t samples() const { return time_s.size(); }
};

}  // namespace aloft::host

namespace aloft::host {

struct ResampledPoses;

// A pose flight from resampled poses: states are the poses with the curve's body rate;
// measured rates come from consecutive orientations (aloft::omega_body_from_orientations).
StudyFlight make_pose_flight(const std::string& name, const ResampledPoses& poses);

// A rate flight from gyro samples already in body axes.
StudyFlight make_rate_flight(const std::string& name, const std::vector<double>& time_s,
                             const std::vector<Eigen::Vector3d>& omega_body);

}  // namespace aloft::host
