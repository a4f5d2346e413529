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
#include <initializer_list>
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

// The dot product of two columns of length n.
template <typename Scalar>
inline Scalar column_dot(const Scalar* a, const Scalar* b, int n) {
  Scalar sum = Scalar(0);
  for (int k = 0; k < n; ++k) sum += a[k] * b[k];
  return sum;
}

// One-sided Jacobi on the n x n matrices x and v (column-major, columns of length n): x's
// columns rotated until orthogonal, v <- v R alike, then values(k) = |x_k|², ascending, the
// columns of v and x sorted with them. The size is an argument, not a template's: the 3 x 3
// and the 6 x 6 of the tensor estimate share one copy of the code in a firmware's flash.
// Returns whether the sort swapped columns an odd number of times: the rotations keep v's
// determinant, so v, started at the identity, then has determinant -1.
template <typename Scalar>
ALOFT_COLD inline bool gram_eigen_columns(Scalar* x, Scalar* v, Scalar* values, int n) {
  const Scalar eps = std::numeric_limits<Scalar>::epsilon();
  for (int sweep = 0; sweep < 32; ++sweep) {
    bool rotated = false;
    for (int p = 0; p < n - 1; ++p) {
      for (int q = p + 1; q < n; ++q) {
        Scalar* xp = x + p * n;
        Scalar* xq = x + q * n;
        const Scalar app = column_dot(xp, xp, n), aqq = column_dot(xq, xq, n), apq = column_dot(xp, xq, n);
        if (!(std::abs(apq) > eps * std::sqrt(app * aqq))) continue;
        rotated = true;
        Scalar c, s;
        jacobi_rotation(app, aqq, apq, c, s);
        for (Scalar* m : {x, v}) {
          for (int k = 0; k < n; ++k) {
            const Scalar mp = m[p * n + k], mq = m[q * n + k];
            m[p * n + k] = c * mp - s * mq;
            m[q * n + k] = s * mp + c * mq;
          }
        }
      }
    }
    if (!rotated) break;
  }
  for (int k = 0; k < n; ++k) values[k] = column_dot(x + k * n, x + k * n, n);
  bool odd = false;
  for (int i = 0; i < n; ++i) {  // ascending, the columns carried along
    for (int j = i + 1; j < n; ++j) {
      if (!(values[j] < values[i])) continue;
      odd = !odd;
      std::swap(values[i], values[j]);
      for (int k = 0; k < n; ++k) {
        std::swap(v[i * n + k], v[j * n + k]);
        std::swap(x[i * n + k], x[j * n + k]);
      }
    }
  }
  return odd;
}

}  // namespace detail

// The eigen-decomposition of X^T X without forming it: X's columns are rotated (X <- X V)
// until they are orthogonal; then values(k) = |x_k|² (ascending, x's columns sorted with
// them) and X^T X = V diag(values) V^T. The small eigenvalues keep the precision of X, not
// of X^T X: in float a ratio of smallest to largest eigenvalue of 1e-10 still comes out to
// a few per cent, where forming X^T X leaves only rounding below about 1e-7.
// Returns whether `vectors` came out with determinant -1 (a reflection).
template <typename Scalar, int N>
inline bool gram_eigen_decomposition(Eigen::Matrix<Scalar, N, N>& x, Eigen::Matrix<Scalar, N, 1>& values,
                                     Eigen::Matrix<Scalar, N, N>& vectors) {
  vectors.setIdentity();
  return detail::gram_eigen_columns(x.data(), vectors.data(), values.data(), N);
}

// The eigen-decomposition of a positive definite 3 x 3 `a` (an inertia tensor) through its
// Cholesky factor, a = L L^T = X^T X with X = L^T, by the one-sided Jacobi above: the same
// code as the 6 x 6 Gram matrix's (a firmware that estimates a tensor holds one copy), the
// small moment to the precision of X. values ascending, vectors right-handed. False, and
// nothing filled, when `a` is not positive definite.
template <typename Scalar>
inline bool positive_definite_eigen_decomposition(const Mat3<Scalar>& a, Vec3<Scalar>& values,
                                                  Mat3<Scalar>& vectors) {
  Mat3<Scalar> x = Mat3<Scalar>::Zero();  // L^T, upper triangular
  for (int j = 0; j < 3; ++j) {
    Scalar d = a(j, j);
    for (int k = 0; k < j; ++k) d -= x(k, j) * x(k, j);
    if (!(d > Scalar(0))) return false;
    x(j, j) = std::sqrt(d);
    for (int i = j + 1; i < 3; ++i) {
      Scalar e = a(j, i);
      for (int k = 0; k < j; ++k) e -= x(k, j) * x(k, i);
      x(j, i) = e / x(j, j);
    }
  }
  if (gram_eigen_decomposition(x, values, vectors)) vectors.col(2) = -vectors.col(2);
  return true;
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
