#include "diagnose/1_input/body_kinematics.hpp"

namespace aloft::host::diagnose {

BodyKinematics<double> body_kinematics_at(const std::vector<double>& time_s,
                                          const std::vector<Eigen::Vector3d>& gyro_rad_s,
                                          const std::vector<Eigen::Vector3d>& accel_m_s2,
                                          const Eigen::Matrix3d& to_body, std::size_t k) {
  std::size_t lo = k, hi = k;
  while (lo > 0 && time_s[k] - time_s[lo] < kDerivativeHalfSpan_s) --lo;
  while (hi + 1 < time_s.size() && time_s[hi] - time_s[k] < kDerivativeHalfSpan_s) ++hi;
  BodyKinematics<double> kin;
  kin.w = to_body * gyro_rad_s[k];
  if (hi > lo) kin.w_dot = to_body * (gyro_rad_s[hi] - gyro_rad_s[lo]) / (time_s[hi] - time_s[lo]);
  kin.a = to_body * accel_m_s2[k];
  return kin;
}

}  // namespace aloft::host::diagnose
