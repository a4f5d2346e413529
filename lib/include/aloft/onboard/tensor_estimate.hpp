// The tensor a flight shows, from the normal equations of its pieces
// (aloft/onboard/tensor_estimator.hpp keeps them as the samples come): the flight's end, a
// cold path run once per flight. docs/tensor-estimate.md derives it and gives the
// measurements behind its thresholds.
//
// The unknowns are the tensor's six entries scaled by a nominal moment,
// theta = (Ixx, Iyy, Izz, Ixy, Ixz, Iyz) / scale; each piece of flight gave three rows
// A theta = b of Euler's equations integrated over it, and the stream kept N = A^T A,
// g = A^T b and b^T b.
//  - Torque-free (no rotor, b = 0): the flight fixes theta up to its scale, as N's
//    eigenvector of the smallest eigenvalue: principal ratios and axes.
//  - With a rotor's known momentum in b: theta = N^-1 g, absolute moments.
// Intervals: the rows' noise variance from the residuals (RSS / (rows - unknowns)), the
// covariance of theta from it and N (pseudo-inverse orthogonal to theta when scale-free),
// carried to ratios, moments and axes by the delta method (perturbation theory), 95 %
// with Student's t for the residuals' degrees of freedom.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "aloft/cold_path.hpp"
#include "aloft/dynamics/rotation.hpp"
#include "aloft/dynamics/symmetric_eigen.hpp"

namespace aloft {

// Why an estimate is not determined (TensorEstimate::note).
enum class TensorEstimateNote : std::uint8_t {
  determined = 0,      // the flight fixes the ratios and the axes
  too_short,           // too few pieces of flight
  too_little_turning,  // the body hardly turned (a drop)
  one_axis_spin,       // the rates do not fix the tensor: a spin about one principal axis
  not_a_tensor,        // the fit is no physical tensor (not positive definite)
};

constexpr const char* describe(TensorEstimateNote n) {
  switch (n) {
    case TensorEstimateNote::determined: return "determined";
    case TensorEstimateNote::too_short: return "too short: too few pieces of flight to fit the tensor";
    case TensorEstimateNote::too_little_turning: return "too little turning to see the tensor (a drop?)";
    case TensorEstimateNote::one_axis_spin:
      return "the rates do not fix the tensor (a spin about one principal axis?)";
    case TensorEstimateNote::not_a_tensor: return "the fit is not a physical tensor (not positive definite)";
  }
  return "unknown";
}

template <typename Scalar>
struct TensorEstimate {
  // The quaternion first: Eigen aligns it to 16 bytes, and behind the flags it left 16
  // bytes of padding (80 B, not 64, in float).
  Quat<Scalar> axes = Quat<Scalar>::Identity();  // principal frame into body axes
  // Principal moments, ascending: kg·m² when absolute, else scaled so that the largest is 1
  // (principal(0), principal(1) are then the ratios I1/I3, I2/I3).
  Vec3<Scalar> principal = Vec3<Scalar>::Zero();
  Vec3<Scalar> principal_95 = Vec3<Scalar>::Zero();  // 95 % half-widths, when absolute
  Scalar ratios_95[2] = {Scalar(0), Scalar(0)};      // 95 % half-widths of I1/I3, I2/I3
  Vec3<Scalar> axes_95_rad = Vec3<Scalar>::Zero();   // each principal axis held within (95 %)
  bool determined = false;
  bool absolute = false;  // principal is in kg·m²: a rotor's known momentum gave the scale
  TensorEstimateNote note = TensorEstimateNote::too_short;

  Scalar ratio(int i) const { return principal(i) / principal(2); }
};

namespace detail {
// The right side b's part of the problem: kept only where a rotor may give b (RightSide);
// torque-free rows have b = 0, and a firmware without rotor support keeps 28 B less.
template <typename Scalar, bool RightSide>
struct LeastSquaresRightSide {
  Scalar z[6] = {};        // the right side, rotated with R
  Scalar rss = Scalar(0);  // residual sum of squares of b's part
  // A^T G, row by row (6 x 3): the normal equations' right sides for the gyro reading each
  // axis a fraction too high, G's rows the rows' sensitivities (in rows' units) to it. A
  // rotor's scale hangs on the gyro's: these give the absolute moments' share of it.
  Scalar gyro_scale[18] = {};
  Scalar gyro_scale_squares[6] = {};  // G^T G: 00 11 22 01 02 12
  Scalar gyro_scale_b[3] = {};        // G^T b

  // Before the row is rotated in (add_row overwrites it).
  ALOFT_COLD void add_gyro_scale_sensitivity(const Scalar (&a)[6], const Scalar (&g)[3], Scalar b) {
    for (int m = 0; m < 6; ++m)
      for (int k = 0; k < 3; ++k) gyro_scale[3 * m + k] += a[m] * g[k];
    const int row[6] = {0, 1, 2, 0, 0, 1}, col[6] = {0, 1, 2, 1, 2, 2};
    for (int e = 0; e < 6; ++e) gyro_scale_squares[e] += g[row[e]] * g[col[e]];
    for (int k = 0; k < 3; ++k) gyro_scale_b[k] += g[k] * b;
  }
};
template <typename Scalar>
struct LeastSquaresRightSide<Scalar, false> {};
}  // namespace detail

// What a flight's pieces left (aloft/onboard/tensor_estimator.hpp), in theta's scaled units:
// the least-squares problem A theta = b in square-root form, R theta = z with R upper
// triangular, each piece's rows rotated in as they come (Givens), and the residual sum of
// squares those rotations leave. Not N = A^T A: summed in float, N keeps nothing of a
// residual below 1e-7 of its largest eigenvalue, and a gyro's noise against a throw's
// rates lies near 1e-8 (docs/tensor-estimate.md); R keeps the square root of that ratio.
template <typename Scalar, bool RightSide = true>
struct TensorLeastSquares : detail::LeastSquaresRightSide<Scalar, RightSide> {
  Scalar r[21] = {};                  // R's upper triangle, row by row
  Scalar rate_squared_s = Scalar(0);  // sum over the pieces of ∫ |w|² dt, rad²/s

  // One row a theta = b, rotated into R. Cold: three rows a piece, once every tens of ms.
  ALOFT_COLD void add_row(Scalar (&a)[6], Scalar b) {
    int k = 0;  // r's index of R(i, i)
    for (int i = 0; i < 6; k += 6 - i, ++i) {
      if (!(std::abs(a[i]) > Scalar(0))) continue;
      const Scalar rho = std::sqrt(r[k] * r[k] + a[i] * a[i]);
      const Scalar c = r[k] / rho, s = a[i] / rho;
      r[k] = rho;
      for (int j = i + 1; j < 6; ++j) {
        const Scalar rj = r[k + j - i];
        r[k + j - i] = c * rj + s * a[j];
        a[j] = c * a[j] - s * rj;
      }
      if constexpr (RightSide) {
        const Scalar zi = this->z[i];
        this->z[i] = c * zi + s * b;
        b = c * b - s * zi;
      }
    }
    if constexpr (RightSide) this->rss += b * b;
  }
  Eigen::Matrix<Scalar, 6, 6> r_matrix() const {
    Eigen::Matrix<Scalar, 6, 6> m = Eigen::Matrix<Scalar, 6, 6>::Zero();
    int k = 0;
    for (int i = 0; i < 6; ++i)
      for (int j = i; j < 6; ++j) m(i, j) = r[k++];
    return m;
  }
};

// How many pieces went in, and whether any had a rotor's momentum (b fixes the scale).
struct TensorPieces {
  std::uint16_t count = 0;
  bool scaled = false;
};

// What decides whether a flight determines the tensor (TensorEstimatorSettings holds them).
template <typename Scalar>
struct TensorDetermination {
  std::uint16_t min_pieces;
  Scalar min_rms_rate_rad_s;
  Scalar max_relative_sd;
  std::uint32_t piece_us;  // the pieces last at least this long
};

// The gyro's sensitivity error the intervals of an absolute estimate allow for, each axis:
// a MEMS gyro's scale after its factory trim and over temperature is within ±1 % in 95 %
// of parts (taken as normal: standard deviation 1 % / 1.96; the generated throws draw it
// uniformly within ±1 %). The moments hang on it directly: it was most
// of their error on generated rotor throws (docs/tensor-estimate.md, "Limits"). A build
// constant, not a setting: a setting would change the records' settings hash, and with it
// their version.
constexpr double gyro_scale_tolerance = 0.01;

namespace detail {

template <typename Scalar>
using Vec6 = Eigen::Matrix<Scalar, 6, 1>;

// The symmetric tensor of theta's six entries.
template <typename Scalar>
inline Mat3<Scalar> tensor_of(const Vec6<Scalar>& t) {
  Mat3<Scalar> m;
  m << t(0), t(3), t(4), t(3), t(1), t(5), t(4), t(5), t(2);
  return m;
}

// u^T T w for the symmetric tensor T of theta's six entries t.
template <typename Scalar>
inline Scalar symmetric_form(const Scalar* t, const Scalar* u, const Scalar* w) {
  return t[0] * u[0] * w[0] + t[1] * u[1] * w[1] + t[2] * u[2] * w[2] + t[3] * (u[0] * w[1] + u[1] * w[0]) +
         t[4] * (u[0] * w[2] + u[2] * w[0]) + t[5] * (u[1] * w[2] + u[2] * w[1]);
}

// Student's t 97.5 % quantile for nu degrees of freedom (Cornish-Fisher from the normal's
// 1.96: 2.226 at nu = 10 against 2.228, exact to 1e-3 from nu = 15).
template <typename Scalar>
inline Scalar t_quantile_975(Scalar nu) {
  return Scalar(1.959964) + Scalar(2.372403) / nu + Scalar(2.822618) / (nu * nu);
}

// The angle within which an axis is held (95 %) from the 2 x 2 covariance (a, b; b, d) of
// its tilt: |tilt|² is a weighted sum of two chi-squares, taken as c chi²(nu) with the same
// mean and variance (Satterthwaite), nu from 1 (one tilt) to 2 (round), whose 95 %
// quantile runs from 3.841 to 5.991 (linear between them).
template <typename Scalar>
inline Scalar axis_angle_95(Scalar a, Scalar b, Scalar d, Scalar t_over_z) {
  const Scalar sum = a + d, squares = a * a + d * d + Scalar(2) * b * b;
  if (!(squares > Scalar(0))) return Scalar(0);
  const Scalar c = squares / sum, nu = sum * sum / squares;
  const Scalar q = Scalar(3.841459) + (nu - Scalar(1)) * Scalar(5.991465 - 3.841459);
  return std::sqrt(c * q) * t_over_z;
}

// The covariance of theta, carried to the figures by first-order perturbation theory of
// the tensor's eigen-decomposition I = V diag(m) V^T (the delta method, its Jacobian
// exact): along a direction d of theta, with M = V^T I(d) V, the moments move by M_ii and
// principal axis i turns towards axis j by M_ji / (m_i - m_j). theta's covariance is
// sum_k weight[k] v_k v_k^T over N's eigenvectors v_k, so each v_k is one such direction.
// (A central difference in float, h = eps^(1/3), mixed the axes of moments within 0.5 %
// of each other and got some intervals 3 times too narrow.)
// m and axes: theta's tensor decomposed (the caller's frame: not stacked on this one's).
template <typename Scalar>
ALOFT_COLD inline void propagate(const Vec3<Scalar>& m, const Mat3<Scalar>& axes,
                                 const Eigen::Matrix<Scalar, 6, 6>& vectors, const Vec6<Scalar>& weight,
                                 Scalar t, TensorEstimate<Scalar>& out) {
  Scalar var[5] = {};
  Scalar tilt[6] = {};  // the tilts' covariance: 00 11 22 01 02 12
  const int row[6] = {0, 1, 2, 0, 0, 1}, col[6] = {0, 1, 2, 1, 2, 2};
  for (int k = 0; k < 6; ++k) {
    if (!(weight(k) > Scalar(0))) continue;
    // d[e] = (V^T I(v_k) V)(row[e], col[e]), each from I(v_k)'s six entries (no 3 x 3
    // products: Eigen's unrolled ones took 730 B of the flight image's flash).
    Scalar d[6];
    for (int e = 0; e < 6; ++e)
      d[e] = symmetric_form(vectors.col(k).data(), axes.col(row[e]).data(), axes.col(col[e]).data());
    const Scalar u[5] = {(d[0] * m(2) - m(0) * d[2]) / (m(2) * m(2)),
                         (d[1] * m(2) - m(1) * d[2]) / (m(2) * m(2)), d[0], d[1], d[2]};
    for (int i = 0; i < 5; ++i) var[i] += weight(k) * u[i] * u[i];
    const Scalar phi[3] = {d[5] / (m(1) - m(2)), d[4] / (m(2) - m(0)), d[3] / (m(0) - m(1))};
    for (int e = 0; e < 6; ++e) tilt[e] += weight(k) * phi[row[e]] * phi[col[e]];
  }
  out.ratios_95[0] = t * std::sqrt(var[0]);
  out.ratios_95[1] = t * std::sqrt(var[1]);
  for (int i = 0; i < 3; ++i) out.principal_95(i) = t * std::sqrt(var[2 + i]);
  const Scalar t_over_z = t / Scalar(1.959964);
  out.axes_95_rad(0) = axis_angle_95(tilt[1], tilt[5], tilt[2], t_over_z);
  out.axes_95_rad(1) = axis_angle_95(tilt[0], tilt[4], tilt[2], t_over_z);
  out.axes_95_rad(2) = axis_angle_95(tilt[0], tilt[3], tilt[1], t_over_z);
}

// theta's tensor decomposed and its figures with their intervals. Its own frame: the
// decomposition's locals are not on the stack while theta is solved for.
template <typename Scalar>
ALOFT_COLD inline void describe(const Vec6<Scalar>& theta, const Eigen::Matrix<Scalar, 6, 6>& vectors,
                                const Vec6<Scalar>& weight, Scalar t, TensorEstimate<Scalar>& out) {
  Vec3<Scalar> m;
  Mat3<Scalar> axes;
  // Not positive definite (no physical tensor): out keeps its zero moments, which the
  // caller reads as not a tensor.
  if (!positive_definite_eigen_decomposition(tensor_of(theta), m, axes)) return;
  propagate(m, axes, vectors, weight, t, out);
  // Unit to rounding as it stands: the Jacobi rotations keep the axes orthonormal to a few
  // eps, and the record rebuilds w from x, y, z (normalising took 118 B of flash).
  out.axes = Quat<Scalar>(axes);
  out.principal = m;
}

// Singular values of R (square roots of N's eigenvalues) below this fraction of its
// largest are rounding, not information. One-sided Jacobi gets them to about eps of the
// largest: noise-free spins about each principal axis left the second smallest at 1.05 eps
// in float and 1.0 eps in double at most, where noise-free throws held it at 0.03-0.27,
// and a spin wobbling 0.2 % off its axis at 9e-5 (docs/tensor-estimate.md). 64 eps lies
// far from both.
template <typename Scalar>
constexpr Scalar rounding_floor() {
  return Scalar(64) * std::numeric_limits<Scalar>::epsilon();
}

// Theta and the weights of its covariance along N's eigenvectors (ascending eigenvalues
// `values`). Scale-free: theta is the first eigenvector, |theta| = 1, and its residual
// sum of squares the first eigenvalue; false when the gap to the second leaves theta's
// weakest direction more than max_relative_sd uncertain.
template <typename Scalar>
inline bool solve_scale_free(const Vec6<Scalar>& values, const Eigen::Matrix<Scalar, 6, 6>& vectors,
                             Scalar rows, Scalar max_relative_sd, Vec6<Scalar>& theta, Vec6<Scalar>& weight,
                             Scalar& dof) {
  dof = rows - Scalar(5);
  theta = vectors.col(0);
  if (theta.template head<3>().sum() < Scalar(0)) theta = -theta;  // a positive trace
  const Scalar variance = values(0) / dof;
  weight(0) = Scalar(0);  // theta's own direction: its scale, which nothing fixes
  for (int k = 1; k < 6; ++k) {
    const Scalar gap = values(k) - values(0);
    weight(k) =
        gap > Scalar(0) ? variance * values(k) / (gap * gap) : std::numeric_limits<Scalar>::infinity();
  }
  const Scalar floor = rounding_floor<Scalar>();
  return values(1) > floor * floor * values(5) && std::sqrt(weight(1)) <= max_relative_sd;
}

// With the scale: theta = N^-1 g from R's decomposition (x: R's columns rotated, x_k = R v_k),
// the residual sum of squares as the rotations left it.
template <typename Scalar>
inline bool solve_scaled(const TensorLeastSquares<Scalar, true>& ls, Scalar rows, const Vec6<Scalar>& values,
                         const Eigen::Matrix<Scalar, 6, 6>& vectors, const Eigen::Matrix<Scalar, 6, 6>& x,
                         Scalar max_relative_sd, Vec6<Scalar>& theta, Vec6<Scalar>& weight, Scalar& dof) {
  dof = rows - Scalar(6);
  const Vec6<Scalar> z = Eigen::Map<const Vec6<Scalar>>(ls.z);
  const Scalar variance = ls.rss / dof;
  theta.setZero();
  for (int k = 0; k < 6; ++k) {
    if (!(values(k) > Scalar(0))) {
      weight(k) = std::numeric_limits<Scalar>::infinity();
      continue;
    }
    theta += vectors.col(k) * (x.col(k).dot(z) / values(k));
    weight(k) = variance / values(k);
  }
  const Scalar floor = rounding_floor<Scalar>();
  return values(0) > floor * floor * values(5) && std::sqrt(weight(0)) <= max_relative_sd * theta.norm();
}

// N's eigen-decomposition from R, theta and its covariance's weights; false when the flight
// does not fix theta. Its own frame: R's working copy is gone before the intervals are
// carried to the figures (the stack of a firmware's flight end). MayBeScaled: whether a
// rotor may have given the scale (without, the scaled solve is not compiled in).
template <typename Scalar, bool MayBeScaled>
ALOFT_COLD inline bool solve_tensor(const TensorLeastSquares<Scalar, MayBeScaled>& ls, TensorPieces pieces,
                                    Scalar max_relative_sd, Eigen::Matrix<Scalar, 6, 6>& vectors,
                                    Vec6<Scalar>& theta, Vec6<Scalar>& weight, Scalar& dof) {
  Eigen::Matrix<Scalar, 6, 6> x = ls.r_matrix();
  Vec6<Scalar> values;
  gram_eigen_decomposition(x, values, vectors);
  const Scalar rows = Scalar(3) * static_cast<Scalar>(pieces.count);
  if constexpr (MayBeScaled) {
    if (pieces.scaled) return solve_scaled(ls, rows, values, vectors, x, max_relative_sd, theta, weight, dof);
  }
  return solve_scale_free(values, vectors, rows, max_relative_sd, theta, weight, dof);
}

// x = N^-1 y = R^-1 R^-T y by two triangular solves; false when R is singular.
template <typename Scalar>
inline bool solve_normal_equations(const Scalar (&r)[21], Vec6<Scalar>& x) {
  int k = 0;
  for (int i = 0; i < 6; k += 6 - i, ++i) {  // R^T z = y: forward
    if (!(r[k] > Scalar(0))) return false;
    x(i) /= r[k];
    for (int j = i + 1; j < 6; ++j) x(j) -= r[k + j - i] * x(i);
  }
  for (int i = 5; i >= 0; --i) {  // R x = z: backward
    k -= 6 - i;
    for (int j = i + 1; j < 6; ++j) x(i) -= r[k + j - i] * x(j);
    x(i) /= r[k];
  }
  return true;
}

// A^T g_k: the normal equations' right side for a scale error on the gyro's axis k.
template <typename Scalar>
inline Vec6<Scalar> gyro_scale_right_side(const TensorLeastSquares<Scalar, true>& ls, int k) {
  Vec6<Scalar> y;
  for (int m = 0; m < 6; ++m) y(m) = ls.gyro_scale[3 * m + k];
  return y;
}

// The share of the residual sum of squares that is noise once the gyro's three scale errors
// are fitted to the residuals r = b - A theta (regressed on (I - H) G, H the fit's hat
// matrix): scale errors are constant over a flight and leave residuals of their own, which
// the noise's variance must not count twice. response.col(k) = N^-1 A^T g_k.
template <typename Scalar>
inline Scalar noise_share_beyond_gyro_scale(const TensorLeastSquares<Scalar, true>& ls,
                                            const Eigen::Matrix<Scalar, 6, 3>& response,
                                            const Vec6<Scalar>& theta, Scalar dof) {
  if (!(ls.rss > Scalar(0)) || !(dof > Scalar(3))) return Scalar(1);
  Mat3<Scalar> gg;  // G^T (I - H) G = G^T G - (A^T G)^T N^-1 A^T G
  Vec3<Scalar> gr;  // G^T r
  const int row[6] = {0, 1, 2, 0, 0, 1}, col[6] = {0, 1, 2, 1, 2, 2};
  for (int e = 0; e < 6; ++e) {
    const Scalar v = ls.gyro_scale_squares[e] - gyro_scale_right_side(ls, row[e]).dot(response.col(col[e]));
    gg(row[e], col[e]) = gg(col[e], row[e]) = v;
  }
  for (int k = 0; k < 3; ++k) gr(k) = ls.gyro_scale_b[k] - gyro_scale_right_side(ls, k).dot(theta);
  const Scalar explained = gr.dot(Eigen::LDLT<Mat3<Scalar>>(gg).solve(gr));
  return std::max(Scalar(1) - explained / ls.rss, Scalar(0)) * dof / (dof - Scalar(3));
}

// Widens an absolute estimate's intervals (theta's units, before the scale) by the gyro's
// scale tolerance: theta moves by N^-1 A^T g_k per unit scale error on axis k (least
// squares' first-order response to rows off by g_k), each error normal with standard
// deviation tolerance / 1.96, carried to the figures as the noise is (propagate) and added
// in quadrature to the noise's share, itself narrowed to the residuals the scale errors do
// not explain. Generated rotor flights whose gyro's scale is off as assumed: covered in
// 95.7-96.7 % (tests/host/test_tensor_coverage.cpp); not narrowed, 98.3-99.3 %.
template <typename Scalar>
ALOFT_COLD inline void widen_for_gyro_scale(const TensorLeastSquares<Scalar, true>& ls,
                                            const Vec6<Scalar>& theta, Scalar dof,
                                            TensorEstimate<Scalar>& out) {
  Eigen::Matrix<Scalar, 6, 6> directions = Eigen::Matrix<Scalar, 6, 6>::Zero();
  Vec6<Scalar> weight = Vec6<Scalar>::Zero();
  for (int k = 0; k < 3; ++k) {
    Vec6<Scalar> x = gyro_scale_right_side(ls, k);
    if (!solve_normal_equations(ls.r, x)) return;
    directions.col(k) = x;
    weight(k) = static_cast<Scalar>(gyro_scale_tolerance * gyro_scale_tolerance / (1.959964 * 1.959964));
  }
  const Scalar f =
      std::sqrt(noise_share_beyond_gyro_scale<Scalar>(ls, directions.template leftCols<3>(), theta, dof));
  Vec3<Scalar> m;
  Mat3<Scalar> axes;
  if (!positive_definite_eigen_decomposition(tensor_of(theta), m, axes)) return;
  TensorEstimate<Scalar> scale_share;
  propagate(m, axes, directions, weight, Scalar(1.959964), scale_share);
  const auto add = [f](Scalar& a, Scalar b) { a = std::sqrt(f * f * a * a + b * b); };
  for (int i = 0; i < 2; ++i) add(out.ratios_95[i], scale_share.ratios_95[i]);
  for (int i = 0; i < 3; ++i) add(out.principal_95(i), scale_share.principal_95(i));
  for (int i = 0; i < 3; ++i) add(out.axes_95_rad(i), scale_share.axes_95_rad(i));
}

}  // namespace detail

// The estimate from a flight's least-squares problem; `scale` is theta's unit in kg·m².
template <typename Scalar, bool MayBeScaled = true>
ALOFT_COLD inline void estimate_tensor(const TensorLeastSquares<Scalar, MayBeScaled>& ls, TensorPieces pieces,
                                       Scalar scale, const TensorDetermination<Scalar>& d,
                                       TensorEstimate<Scalar>& out) {
  out = TensorEstimate<Scalar>();
  if (pieces.count < d.min_pieces) return;  // too_short
  const Scalar time_s = static_cast<Scalar>(pieces.count) * static_cast<Scalar>(d.piece_us) * Scalar(1e-6);
  if (!(ls.rate_squared_s > d.min_rms_rate_rad_s * d.min_rms_rate_rad_s * time_s)) {
    out.note = TensorEstimateNote::too_little_turning;
    return;
  }
  Eigen::Matrix<Scalar, 6, 6> vectors;
  detail::Vec6<Scalar> theta, weight;
  Scalar dof = Scalar(0);
  if (!detail::solve_tensor<Scalar, MayBeScaled>(ls, pieces, d.max_relative_sd, vectors, theta, weight,
                                                 dof)) {
    out.note = TensorEstimateNote::one_axis_spin;
    return;
  }
  detail::describe(theta, vectors, weight, detail::t_quantile_975(dof), out);
  if (!(out.principal(0) > Scalar(0))) {
    out.note = TensorEstimateNote::not_a_tensor;
    return;
  }
  out.determined = true;
  out.note = TensorEstimateNote::determined;
  out.absolute = pieces.scaled;
  if constexpr (MayBeScaled) {
    if (out.absolute) detail::widen_for_gyro_scale(ls, theta, dof, out);
  }
  if (out.absolute) {
    out.principal *= scale;
    out.principal_95 *= scale;
  } else {
    out.principal /= out.principal(2);
    out.principal_95.setZero();
  }
}

}  // namespace aloft
