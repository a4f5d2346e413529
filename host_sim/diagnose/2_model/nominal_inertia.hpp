// The nominal inertia tensor the diagnosis starts from. Unlike aloft::InertiaTensor it
// does not insist on the triangle inequality: a measured tensor (the racquet's pendulum
// moments break it by 2 %) is still a model whose gap to reality can be diagnosed, and the
// Euler equations integrate it all the same.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "aloft/dynamics/inertia_tensor.hpp"

namespace aloft::host::diagnose {

struct NominalInertia {
  Eigen::Matrix3d tensor = Eigen::Matrix3d::Identity();         // kg·m², body axes
  Eigen::Vector3d principal_moments = Eigen::Vector3d::Ones();  // ascending
  // Maps principal axes into body axes (column i of its matrix: principal axis i).
  Eigen::Quaterniond principal_axes = Eigen::Quaterniond::Identity();
  bool breaks_triangle_inequality = false;

  static NominalInertia of(const InertiaTensor<double>& inertia);
  // Any symmetric positive definite tensor (the caller has checked both).
  static NominalInertia of_tensor(const Eigen::Matrix3d& tensor);
};

}  // namespace aloft::host::diagnose
