#include "diagnose/2_model/effect_parameters.hpp"

#include <cmath>
#include <cstddef>

namespace aloft::host::diagnose {

std::array<int, 3> nearest_body_axes(const Eigen::Matrix3d& axes) {
  std::array<int, 3> body{-1, -1, -1};
  std::array<bool, 3> taken{false, false, false};
  for (int round = 0; round < 3; ++round) {
    double best = -1.0;
    int bi = 0, bj = 0;
    for (int i = 0; i < 3; ++i) {
      if (body[static_cast<std::size_t>(i)] >= 0) continue;
      for (int j = 0; j < 3; ++j) {
        if (taken[static_cast<std::size_t>(j)]) continue;
        if (std::abs(axes(j, i)) > best) {
          best = std::abs(axes(j, i));
          bi = i;
          bj = j;
        }
      }
    }
    body[static_cast<std::size_t>(bi)] = bj;
    taken[static_cast<std::size_t>(bj)] = true;
  }
  return body;
}

void describe_inertia(EffectParameters& p, const Eigen::Vector3d& moments, const Eigen::Matrix3d& axes,
                      const NominalInertia& nominal) {
  p.tensor_kg_m2 = axes * moments.asDiagonal() * axes.transpose();
  const std::array<int, 3> body = nearest_body_axes(nominal.principal_axes.toRotationMatrix());
  for (int i = 0; i < 3; ++i) {
    p.principal_body_order_kg_m2(body[static_cast<std::size_t>(i)]) = moments(i);
    p.nominal_body_order_kg_m2(body[static_cast<std::size_t>(i)]) = nominal.principal_moments(i);
  }
}

}  // namespace aloft::host::diagnose
