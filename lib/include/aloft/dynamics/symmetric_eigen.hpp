// Eigen-decomposition of a symmetric 3x3 matrix by cyclic Jacobi rotations.
//
// Why not Eigen's SelfAdjointEigenSolver::computeDirect: its closed-form cubic goes
// through cos/acos, whose large-argument reduction in newlib (__kernel_rem_pio2f) alone
// reserves 416 bytes of stack on a Cortex-M, and it loses accuracy for nearly equal
// eigenvalues (a near-symmetric body: the paper's cylinder). Jacobi needs only sqrt and
// division, converges quadratically, and is accurate to rounding for any spectrum.
#pragma once

#include <limits>

#include "aloft/cold_path.hpp"

#include "aloft/dynamics/rotation.hpp"

namespace aloft {

// Fills `values` (ascending) and `vectors` (columns, orthonormal, right-handed) with
// A = vectors * diag(values) * vectors^T. `a` must be symmetric and finite.
template <typename Scalar>
ALOFT_COLD inline void symmetric_eigen_decomposition(const Mat3<Scalar>& a, Vec3<Scalar>& values,
                                                     Mat3<Scalar>& vectors) {
  Mat3<Scalar> m = a;
  Mat3<Scalar> v = Mat3<Scalar>::Identity();
  const Scalar eps = std::numeric_limits<Scalar>::epsilon();
  for (int sweep = 0; sweep < 32; ++sweep) {
    const Scalar off = m(0, 1) * m(0, 1) + m(0, 2) * m(0, 2) + m(1, 2) * m(1, 2);
    const Scalar diagonal = m(0, 0) * m(0, 0) + m(1, 1) * m(1, 1) + m(2, 2) * m(2, 2);
    if (!(off > eps * eps * diagonal)) break;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        const Scalar apq = m(p, q);
        if (!(std::abs(apq) > Scalar(0))) continue;
        // Rotation angle that zeroes m(p, q): t = tan(phi), the smaller root.
        const Scalar theta = (m(q, q) - m(p, p)) / (Scalar(2) * apq);
        const Scalar abs_theta = std::abs(theta);
        Scalar t = abs_theta > Scalar(1) / eps
                       ? Scalar(0.5) / theta
                       : Scalar(1) / (abs_theta + std::sqrt(theta * theta + Scalar(1)));
        if (theta < Scalar(0) && !(abs_theta > Scalar(1) / eps)) t = -t;
        const Scalar c = Scalar(1) / std::sqrt(t * t + Scalar(1));
        const Scalar s = t * c;
        Mat3<Scalar> rotation = Mat3<Scalar>::Identity();
        rotation(p, p) = c;
        rotation(q, q) = c;
        rotation(p, q) = s;
        rotation(q, p) = -s;
        m = (rotation.transpose() * m * rotation).eval();
        m(p, q) = Scalar(0);
        m(q, p) = Scalar(0);
        v = (v * rotation).eval();
      }
    }
  }
  // Sort ascending, carrying the vectors along.
  int order[3] = {0, 1, 2};
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      if (m(order[j], order[j]) < m(order[i], order[i])) {
        const int k = order[i];
        order[i] = order[j];
        order[j] = k;
      }
    }
  }
  for (int i = 0; i < 3; ++i) {
    values(i) = m(order[i], order[i]);
    vectors.col(i) = v.col(order[i]);
  }
  if (vectors.determinant() < Scalar(0)) vectors.col(2) = -vectors.col(2);
}

}  // namespace aloft
