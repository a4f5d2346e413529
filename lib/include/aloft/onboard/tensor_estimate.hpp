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
// torque-free rows have b = 0, and a firmware without rotor support keeps 44 B less.
template <typename Scalar, bool RightSide>
struct LeastSquaresRightSide {
  Scalar z[10] = {};       // the right side, rotated with R
  Scalar rss = Scalar(0);  // residual sum of squares of b's part
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
// Where a rotor may give b (RightSide), four unknowns more follow theta's six: the rotor's
// telemetry delay in ms and the gyro's three scale errors (estimate_tensor's nuisances);
// R's first six rows and columns are theta's alone, as without them.
template <typename Scalar, bool RightSide = true>
struct TensorLeastSquares : detail::LeastSquaresRightSide<Scalar, RightSide> {
  static constexpr int columns = RightSide ? 10 : 6;
  Scalar r[columns * (columns + 1) / 2] = {};  // R's upper triangle, row by row
  Scalar rate_squared_s = Scalar(0);           // sum over the pieces of ∫ |w|² dt, rad²/s

  // One row a x = b, rotated into R. Cold: three rows a piece, once every tens of ms.
  ALOFT_COLD void add_row(Scalar (&a)[columns], Scalar b) {
    int k = 0;  // r's index of R(i, i)
    for (int i = 0; i < columns; k += columns - i, ++i) {
      if (!(std::abs(a[i]) > Scalar(0))) continue;
      const Scalar rho = std::sqrt(r[k] * r[k] + a[i] * a[i]);
      const Scalar c = r[k] / rho, s = a[i] / rho;
      r[k] = rho;
      for (int j = i + 1; j < columns; ++j) {
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
  // R's first n rows and columns.
  template <int N = 6>
  Eigen::Matrix<Scalar, N, N> r_matrix() const {
    Eigen::Matrix<Scalar, N, N> m = Eigen::Matrix<Scalar, N, N>::Zero();
    int k = 0;
    for (int i = 0; i < N; ++i, k += columns - N)
      for (int j = i; j < N; ++j) m(i, j) = r[k++];
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

// An absolute estimate's nuisances, fitted with theta (estimate_tensor):
//  - the gyro's scale error on each axis: a MEMS gyro's sensitivity after its factory trim
//    and over temperature is within ±1 % in 95 % of parts (taken as a normal prior,
//    standard deviation 1 % / 1.96; the generated throws draw it uniformly within ±1 %).
//    The absolute moments hang on it directly: it was most of their error on generated
//    rotor throws (docs/tensor-estimate.md, "Limits"). A build constant, not a setting: a
//    setting would change the records' settings hash, and with it their version;
//  - the rotor's speed arriving late (an ESC's telemetry: 1-4 ms, quantised, held), with a
//    prior of 0 ± 10 ms that only keeps the fit solvable when the speed does not change.
constexpr double gyro_scale_tolerance = 0.01;
constexpr double gyro_scale_prior_sd = gyro_scale_tolerance / 1.959964;  // the 95 % bound as a normal's
constexpr double rotor_delay_prior_ms = 10.0;

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
  // Static: as locals, both were copied onto this frame (48 B), which was then the deepest
  // path of the flight image's worst-case stack (STM32F405: 4 B of stack and 16 B of flash
  // less; the release window's dating is now the deepest).
  static constexpr int row[6] = {0, 1, 2, 0, 0, 1}, col[6] = {0, 1, 2, 1, 2, 2};
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

// A prior's row for nuisance column j: weight at j (sigma over the prior's standard
// deviation, sigma the rows' noise), 0 on the right, rotated into R.
template <typename Scalar>
inline void add_prior_row(int j, Scalar weight, TensorLeastSquares<Scalar, true>& fit) {
  Scalar row[TensorLeastSquares<Scalar, true>::columns] = {};
  row[j] = weight;
  fit.add_row(row, Scalar(0));
}

// x = R^-1 x for R the first n x n of a column-major upper-triangular matrix with leading
// dimension ld, in place. By hand: Eigen's triangular solve with a matrix on the right
// side, and its products of these sizes, take blocking space from the heap.
template <typename Scalar, int N>
inline void back_substitute(const Scalar* r, int ld, Scalar* x) {
  for (int i = N - 1; i >= 0; --i) {
    for (int j = i + 1; j < N; ++j) x[i] -= r[i + j * ld] * x[j];
    x[i] /= r[i + i * ld];
  }
}

// theta's covariance (theta and the delay fitted; R's first 7 rows R11 | R12): the noise's,
// sigma² R11^-1 R11^-T, and the gyro's scale errors' from their prior alone, R11^-1 R12
// moving theta per unit scale error. Not the fit's posterior, which learns the scale errors
// from the flight: on generated rotor throws it learnt the rest of the model's errors too
// (a 2nd-order filter taken as 1st-order, the telemetry's hold), and its intervals covered
// the moments in 60 of 79 flights (these: 71 of 77). Where the model is exact they are
// wide: every moment covered (docs/tensor-estimate.md, "Intervals").
template <typename Scalar>
inline Eigen::Matrix<Scalar, 6, 6> scaled_covariance(const Eigen::Matrix<Scalar, 10, 10>& r, Scalar sigma) {
  Eigen::Matrix<Scalar, 7, 10> f;  // R11^-1 [sigma I | sd R12]
  f.template leftCols<7>() = sigma * Eigen::Matrix<Scalar, 7, 7>::Identity();
  f.template rightCols<3>() = static_cast<Scalar>(gyro_scale_prior_sd) * r.template topRightCorner<7, 3>();
  for (int c = 0; c < 10; ++c) back_substitute<Scalar, 7>(r.data(), 10, f.col(c).data());
  return f.template topRows<6>().lazyProduct(f.template topRows<6>().transpose());
}

// With the scale: theta with the nuisances (x = R'^-1 z', the priors' rows in R'); sigma²
// from the residuals of the fit without the priors, over rows - 10; theta's covariance
// (scaled_covariance) decomposed into `vectors` and `weight` (its eigenvalues). False when
// the weakest direction of theta is more than max_relative_sd uncertain, or N (theta's own
// R) is rounding.
template <typename Scalar>
inline bool solve_scaled(const TensorLeastSquares<Scalar, true>& ls, Scalar rows, const Vec6<Scalar>& values,
                         Scalar max_relative_sd, Eigen::Matrix<Scalar, 6, 6>& vectors, Vec6<Scalar>& theta,
                         Vec6<Scalar>& weight, Scalar& dof) {
  dof = rows - Scalar(10);
  if (!(dof > Scalar(0))) return false;
  const Scalar floor = rounding_floor<Scalar>();
  const Scalar sigma = std::max(std::sqrt(ls.rss / dof), floor * ls.r[0]);
  TensorLeastSquares<Scalar, true> fit = ls;
  add_prior_row(6, sigma / static_cast<Scalar>(rotor_delay_prior_ms), fit);
  symmetric_eigen_decomposition(scaled_covariance(fit.template r_matrix<10>(), sigma), weight, vectors);
  weight = weight.cwiseMax(Scalar(0));
  for (int j = 7; j < 10; ++j) add_prior_row(j, sigma / static_cast<Scalar>(gyro_scale_prior_sd), fit);
  theta = fit.template r_matrix<10>()
              .template triangularView<Eigen::Upper>()
              .solve(Eigen::Map<const Eigen::Matrix<Scalar, 10, 1>>(fit.z))
              .template head<6>();
  return values(0) > floor * floor * values(5) && std::sqrt(weight(5)) <= max_relative_sd * theta.norm();
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
    if (pieces.scaled) return solve_scaled(ls, rows, values, max_relative_sd, vectors, theta, weight, dof);
  }
  return solve_scale_free(values, vectors, rows, max_relative_sd, theta, weight, dof);
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
  if (out.absolute) {
    out.principal *= scale;
    out.principal_95 *= scale;
  } else {
    out.principal /= out.principal(2);
    out.principal_95.setZero();
  }
}

}  // namespace aloft
