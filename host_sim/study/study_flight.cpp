#include "study/study_flight.hpp"

#include "aloft/dynamics/angular_velocity.hpp"
#include "study/tangent_spline_resampler.hpp"

namespace aloft::host {

StudyFlight make_pose_flight(const std::string& name, const ResampledPoses& poses) {
  StudyFlight f;
  f.name = name;
  f.time_s = poses.time_s;
  f.orientation = poses.orientation;
  f.state_omega_body = poses.omega_body;
  if (!f.time_s.empty()) {
    f.start_s = f.time_s.front();
    f.end_s = f.time_s.back();
  }
  const std::size_t n = f.time_s.size();
  f.measured_omega_body.resize(n > 0 ? n - 1 : 0, Eigen::Vector3d::Zero());
  for (std::size_t j = 0; j + 1 < n; ++j) {
    // A failed status (bad dt or quaternion) leaves the rate zero, which validation rejects.
    const Status s = omega_body_from_orientations(f.orientation[j], f.orientation[j + 1],
                                                  f.time_s[j + 1] - f.time_s[j], f.measured_omega_body[j]);
    if (s != Status::ok) f.measured_omega_body[j].setZero();
  }
  f.measured_omega_world.resize(f.measured_omega_body.size());
  for (std::size_t j = 0; j < f.measured_omega_body.size(); ++j) {
    f.measured_omega_world[j] = f.orientation[j] * f.measured_omega_body[j];
  }
  return f;
}

StudyFlight make_rate_flight(const std::string& name, const std::vector<double>& time_s,
                             const std::vector<Eigen::Vector3d>& omega_body) {
  StudyFlight f;
  f.name = name;
  f.time_s = time_s;
  f.state_omega_body = omega_body;
  f.measured_omega_body = omega_body;
  if (!time_s.empty()) {
    f.start_s = time_s.front();
    f.end_s = time_s.back();
  }
  return f;
}

}  // namespace aloft::host
