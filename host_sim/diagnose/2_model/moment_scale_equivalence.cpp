#include "diagnose/2_model/moment_scale_equivalence.hpp"

#include <cmath>

namespace aloft::host::diagnose {
namespace {

Eigen::Vector3d coefficients(const Eigen::Vector3d& m) {
  return {(m(1) - m(2)) / m(0), (m(2) - m(0)) / m(1), (m(0) - m(1)) / m(2)};
}

}  // namespace

std::optional<Eigen::Vector3d> scale_mimicking_moments(const Eigen::Vector3d& nominal_moments,
                                                       const Eigen::Vector3d& moments) {
  const Eigen::Vector3d a = coefficients(nominal_moments);
  const Eigen::Vector3d a_wrong = coefficients(moments);
  constexpr double kDistinct = 1e-9;  // relative: equal moments within rounding
  Eigen::Vector3d r;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(a(i)) < kDistinct || std::abs(a_wrong(i)) < kDistinct) return std::nullopt;
    r(i) = a(i) / a_wrong(i);
    if (!(r(i) > 0.0)) return std::nullopt;
  }
  const double product = r.prod();
  Eigen::Vector3d s;
  // v = c w obeys the nominal equations; the readings w = v / c are the nominal body's
  // rates read with gains 1 + s = 1 / c.
  for (int i = 0; i < 3; ++i) s(i) = std::sqrt(product / r(i)) - 1.0;
  return s;
}

bool gyro_along_principal_axes(const Eigen::Quaterniond& principal_axes,
                               const Eigen::Quaterniond& sensor_to_body) {
  // Principal axes in sensor axes: a signed permutation matrix when they coincide.
  const Eigen::Matrix3d m = (sensor_to_body.conjugate() * principal_axes).toRotationMatrix();
  return (m.cwiseAbs().array() > 1.0 - 1e-6).count() == 3;
}

}  // namespace aloft::host::diagnose
