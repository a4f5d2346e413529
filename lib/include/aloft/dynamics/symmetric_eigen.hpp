// Eigen-decomposition of a symmetric N x N matrix by cyclic Jacobi rotations (the 3 x 3 of
// an inertia tensor), and of a Gram matrix X^T X from X itself by the same rotations
// applied to X's columns (one-sided Jacobi: the 6 x 6 least-squares problem of the tensor
// estimate, aloft/onboard/tensor_estimate.hpp).
//
// Why not Eigen's SelfAdjointEigenSolver::computeDirect: its closed-form cubic goes
// through cos/acos, whose large-argument reduction in newlib (__kernel_rem_pio2f) alone
// reserves 416 bytes of stack on a Cortex-M, and it loses accuracy for nearly equal
// eigenvalues (a near-symmetric body: the paper's cylinder). Jacobi needs only sqrt and
// division, converges quadratically, is accurate to rounding for any spectrum, and works
// in place on fixed-size matrices (no heap, float on a Cortex-M4F).
//
// Each rotation touches only rows and columns p and q: the same numbers, to the bit, as
// forming the rotation R and taking R^T A R as full products, which this code did for
// 3 x 3 before (checked on a million random symmetric matrices in float and double on
// x86-64), at O(N) instead of O(N^3) per rotation.
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <utility>

#include "aloft/cold_path.hpp"
#include "aloft/dynamics/rotation.hpp"

namespace aloft {

namespace detail {

// The rotation (c, s) that zeroes m(p, q): t = tan(phi), the smaller root.
template <typename Scalar>
inline void jacobi_rotation(Scalar app, Scalar aqq, Scalar apq, Scalar& c, Scalar& s) {
  const Scalar eps = std::numeric_limits<Scalar>::epsilon();
  const Scalar theta = (aqq - app) / (Scalar(2) * apq);
  const Scalar abs_theta = std::abs(theta);
  Scalar t = abs_theta > Scalar(1) / eps ? Scalar(0.5) / theta
                                         : Scalar(1) / (abs_theta + std::sqrt(theta * theta + Scalar(1)));
  if (theta < Scalar(0) && !(abs_theta > Scalar(1) / eps)) t = -t;
  c = Scalar(1) / std::sqrt(t * t + Scalar(1));
  s = t * c;
}

// m <- R^T m R and v <- v R, R the identity but R(p,p) = R(q,q) = c, R(p,q) = s,
// R(q,p) = -s; m(p, q) is then zero.
template <typename Scalar, int N>
inline void apply_jacobi_rotation(Eigen::Matrix<Scalar, N, N>& m, Eigen::Matrix<Scalar, N, N>& v, int p,
                                  int q, Scalar c, Scalar s) {
  for (int k = 0; k < N; ++k) {  // rows p, q of R^T m
    const Scalar mp = m(p, k), mq = m(q, k);
    m(p, k) = c * mp - s * mq;
    m(q, k) = s * mp + c * mq;
  }
  for (int k = 0; k < N; ++k) {  // columns p, q of (R^T m) R, and of v R
    const Scalar mp = m(k, p), mq = m(k, q);
    m(k, p) = c * mp - s * mq;
    m(k, q) = s * mp + c * mq;
    const Scalar vp = v(k, p), vq = v(k, q);
    v(k, p) = c * vp - s * vq;
    v(k, q) = s * vp + c * vq;
  }
  m(p, q) = Scalar(0);
  m(q, p) = Scalar(0);
}

// Sorts values ascending, carrying the columns of `vectors` (and of `also`) along.
template <typename Scalar, int N>
inline void sort_ascending(Eigen::Matrix<Scalar, N, 1>& values, Eigen::Matrix<Scalar, N, N>& vectors,
                           Eigen::Matrix<Scalar, N, N>* also) {
  for (int i = 0; i < N; ++i) {
    for (int j = i + 1; j < N; ++j) {
      if (values(j) < values(i)) {
        const Scalar t = values(i);
        values(i) = values(j);
        values(j) = t;
        // Element by element: Eigen's column swap took a 96-byte frame in float on the
        // Cortex-M4 (the tensor estimate's deepest path at a flight's end).
        for (int k = 0; k < N; ++k) {
          std::swap(vectors(k, i), vectors(k, j));
          if (also != nullptr) std::swap((*also)(k, i), (*also)(k, j));
        }
      }
    }
  }
}

}  // namespace detail

// The eigen-decomposition of X^T X without forming it: X's columns are rotated (X <- X V)
// until they are orthogonal; then values(k) = |x_k|² (ascending, x's columns sorted with
// them) and X^T X = V diag(values) V^T. The small eigenvalues keep the precision of X, not
// of X^T X: in float a ratio of smallest to largest eigenvalue of 1e-10 still comes out to
// a few per cent, where forming X^T X leaves only rounding below about 1e-7.
template <typename Scalar, int N>
ALOFT_COLD inline void gram_eigen_decomposition(Eigen::Matrix<Scalar, N, N>& x,
                                                Eigen::Matrix<Scalar, N, 1>& values,
                                                Eigen::Matrix<Scalar, N, N>& vectors) {
  vectors.setIdentity();
  const Scalar eps = std::numeric_limits<Scalar>::epsilon();
  for (int sweep = 0; sweep < 32; ++sweep) {
    bool rotated = false;
    for (int p = 0; p < N - 1; ++p) {
      for (int q = p + 1; q < N; ++q) {
        const Scalar app = x.col(p).squaredNorm(), aqq = x.col(q).squaredNorm(), apq = x.col(p).dot(x.col(q));
        if (!(std::abs(apq) > eps * std::sqrt(app * aqq))) continue;
        rotated = true;
        Scalar c, s;
        detail::jacobi_rotation(app, aqq, apq, c, s);
        for (int k = 0; k < N; ++k) {
          const Scalar xp = x(k, p), xq = x(k, q), vp = vectors(k, p), vq = vectors(k, q);
          x(k, p) = c * xp - s * xq;
          x(k, q) = s * xp + c * xq;
          vectors(k, p) = c * vp - s * vq;
          vectors(k, q) = s * vp + c * vq;
        }
      }
    }
    if (!rotated) break;
  }
  for (int k = 0; k < N; ++k) values(k) = x.col(k).squaredNorm();
  detail::sort_ascending(values, vectors, &x);
}

// Fills `values` (ascending) and `vectors` (columns, orthonormal; right-handed for 3 x 3)
// with A = vectors * diag(values) * vectors^T. `a` must be symmetric and finite.
template <typename Scalar, int N>
ALOFT_COLD inline void symmetric_eigen_decomposition(const Eigen::Matrix<Scalar, N, N>& a,
                                                     Eigen::Matrix<Scalar, N, 1>& values,
                                                     Eigen::Matrix<Scalar, N, N>& vectors) {
  Eigen::Matrix<Scalar, N, N> m = a;
  Eigen::Matrix<Scalar, N, N> v = Eigen::Matrix<Scalar, N, N>::Identity();
  const Scalar eps = std::numeric_limits<Scalar>::epsilon();
  for (int sweep = 0; sweep < 32; ++sweep) {
    Scalar off = Scalar(0), diagonal = Scalar(0);
    for (int p = 0; p < N; ++p) {
      diagonal += m(p, p) * m(p, p);
      for (int q = p + 1; q < N; ++q) off += m(p, q) * m(p, q);
    }
    if (!(off > eps * eps * diagonal)) break;
    for (int p = 0; p < N - 1; ++p) {
      for (int q = p + 1; q < N; ++q) {
        const Scalar apq = m(p, q);
        if (!(std::abs(apq) > Scalar(0))) continue;
        Scalar c, s;
        detail::jacobi_rotation(m(p, p), m(q, q), apq, c, s);
        detail::apply_jacobi_rotation(m, v, p, q, c, s);
      }
    }
  }
  // Sort ascending, carrying the vectors along.
  int order[N];
  for (int i = 0; i < N; ++i) order[i] = i;
  for (int i = 0; i < N; ++i) {
    for (int j = i + 1; j < N; ++j) {
      if (m(order[j], order[j]) < m(order[i], order[i])) {
        const int k = order[i];
        order[i] = order[j];
        order[j] = k;
      }
    }
  }
  for (int i = 0; i < N; ++i) {
    values(i) = m(order[i], order[i]);
    vectors.col(i) = v.col(order[i]);
  }
  if (N == 3 && vectors.determinant() < Scalar(0)) vectors.col(N - 1) = -vectors.col(N - 1);
}

}  // namespace aloft
