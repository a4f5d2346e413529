#include "diagnose/4_judge/momentum_moment_equivalence.hpp"

#include <cmath>

namespace aloft::host::diagnose {

std::optional<Eigen::Vector3d> moments_mimicking_momentum(const NominalInertia& nominal,
                                                          const Eigen::Vector3d& h, double axial_rate,
                                                          double relative) {
  const Eigen::Vector3d& m = nominal.principal_moments;
  // The axis of revolution: the moment apart from the two equal ones.
  int axis = -1;
  if (std::abs(m(0) - m(1)) <= relative * m(1)) axis = 2;
  if (std::abs(m(1) - m(2)) <= relative * m(2)) axis = axis < 0 ? 0 : -1;  // a sphere has none
  if (axis < 0 || !(std::abs(axial_rate) > 0.0)) return std::nullopt;
  const Eigen::Vector3d e = nominal.principal_axes.toRotationMatrix().col(axis);
  const double along = h.dot(e);
  if ((h - along * e).norm() > relative * h.norm()) return std::nullopt;
  Eigen::Vector3d out = m;
  out(axis) += along / axial_rate;
  if (!(out(axis) > 0.0)) return std::nullopt;
  return out;
}

}  // namespace aloft::host::diagnose
