#include "diagnose/2_model/nominal_inertia.hpp"

#include <Eigen/Eigenvalues>

namespace aloft::host::diagnose {

NominalInertia NominalInertia::of(const InertiaTensor<double>& inertia) {
  NominalInertia n;
  n.tensor = inertia.tensor();
  n.principal_moments = inertia.principal_moments();
  n.principal_axes = inertia.principal_axes();
  return n;
}

NominalInertia NominalInertia::of_tensor(const Eigen::Matrix3d& tensor) {
  NominalInertia n;
  n.tensor = 0.5 * (tensor + tensor.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(n.tensor);
  n.principal_moments = solver.eigenvalues();
  Eigen::Matrix3d axes = solver.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);
  n.principal_axes = Eigen::Quaterniond(axes).normalized();
  const Eigen::Vector3d& m = n.principal_moments;
  n.breaks_triangle_inequality = m(2) > m(0) + m(1);
  return n;
}

}  // namespace aloft::host::diagnose
