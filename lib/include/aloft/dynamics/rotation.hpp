// Conventions of aloft, fixed here once for the whole project (SPEC §1):
//  - Quaternions are Hamilton (i*j = k), written and stored in the order w, x, y, z.
//    Eigen::Quaternion stores [x, y, z, w] internally and its four-number constructor
//    takes (w, x, y, z); always build them through the helpers below, never from raw
//    storage.
//  - q maps body to world: v_world = q * v_body * q^-1, i.e. R(q) * v_body.
//  - Kinematics: dq/dt = 1/2 * q * (0, w_body); w_world = R(q) * w_body.
//  - Scalars are float or double; every function is a template over Scalar and never
//    promotes float to double (the Cortex-M4F FPU is single precision).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace aloft {

template <typename Scalar>
using Vec3 = Eigen::Matrix<Scalar, 3, 1>;
template <typename Scalar>
using Mat3 = Eigen::Matrix<Scalar, 3, 3>;
template <typename Scalar>
using Quat = Eigen::Quaternion<Scalar>;

// Tolerances on stored quaternions: a quaternion read from text with 9 significant
// digits, or renormalised in float, passes; one that is plainly not a rotation fails.
template <typename Scalar>
struct UnitTolerance;
template <>
struct UnitTolerance<float> {
  static constexpr float norm_squared = 1e-4f;
};
template <>
struct UnitTolerance<double> {
  static constexpr double norm_squared = 1e-6;
};

template <typename Scalar>
inline Quat<Scalar> quat_wxyz(Scalar w, Scalar x, Scalar y, Scalar z) {
  return Quat<Scalar>(w, x, y, z);
}

template <typename Scalar>
inline bool all_finite(const Vec3<Scalar>& v) {
  return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

// Both vectors at once, with one test: a finite x gives x - x = 0 exactly, an infinity or
// a NaN gives NaN, which the sum carries (a sample's gyro and accelerometer: 15
// instructions on a Cortex-M4F, not 24).
template <typename Scalar>
inline bool all_finite(const Vec3<Scalar>& a, const Vec3<Scalar>& b) {
  return std::isfinite(((a - a) + (b - b)).sum());
}

template <typename Scalar>
inline bool all_finite(const Quat<Scalar>& q) {
  return std::isfinite(q.w()) && std::isfinite(q.x()) && std::isfinite(q.y()) && std::isfinite(q.z());
}

template <typename Scalar>
inline bool is_unit(const Quat<Scalar>& q) {
  return all_finite(q) && std::abs(q.squaredNorm() - Scalar(1)) <= UnitTolerance<Scalar>::norm_squared;
}

// Exponential map: the unit quaternion of rotation vector r (axis * angle, radians).
// Below the small-angle threshold the Taylor series of sin(|r|/2)/|r| is used, so the
// result is exact to rounding down to |r| = 0.
template <typename Scalar>
inline Quat<Scalar> quat_exp(const Vec3<Scalar>& r) {
  const Scalar theta_sq = r.squaredNorm();
  const Scalar half = Scalar(0.5);
  Scalar w;
  Scalar k;  // sin(theta/2) / theta
  if (theta_sq < Scalar(1e-6)) {
    // Errors of the truncated series are O(theta^6) relative: below rounding here.
    w = Scalar(1) - theta_sq / Scalar(8) + theta_sq * theta_sq / Scalar(384);
    k = half - theta_sq / Scalar(48) + theta_sq * theta_sq / Scalar(3840);
  } else {
    const Scalar theta = std::sqrt(theta_sq);
    w = std::cos(half * theta);
    k = std::sin(half * theta) / theta;
  }
  return Quat<Scalar>(w, k * r.x(), k * r.y(), k * r.z());
}

// Logarithm map: the rotation vector (axis * angle, angle in [0, pi]) of unit q.
// Uses atan2 of the vector and scalar parts, which keeps full relative precision for
// tiny angles where acos(w) would lose it, and picks the shorter of q and -q.
template <typename Scalar>
inline Vec3<Scalar> quat_log(const Quat<Scalar>& q) {
  Scalar w = q.w();
  Vec3<Scalar> v = q.vec();
  if (w < Scalar(0)) {
    w = -w;
    v = -v;
  }
  const Scalar s = v.norm();
  if (s < Scalar(1e-6) * w) {
    // angle = 2*atan2(s, w) ~ 2 s/w (1 - s^2/(3 w^2)); relative error O(s^4).
    const Scalar ratio_sq = (s * s) / (w * w);
    return v * (Scalar(2) / w * (Scalar(1) - ratio_sq / Scalar(3)));
  }
  const Scalar angle = Scalar(2) * std::atan2(s, w);
  return v * (angle / s);
}

// Rotation angle between two orientations, 2*atan2(|vec(a^-1 b)|, |w(a^-1 b)|) in
// [0, pi]: resolves angles down to rounding, unlike acos of a dot product.
template <typename Scalar>
inline Scalar angle_between(const Quat<Scalar>& a, const Quat<Scalar>& b) {
  const Quat<Scalar> d = a.conjugate() * b;
  return Scalar(2) * std::atan2(d.vec().norm(), std::abs(d.w()));
}

}  // namespace aloft
