// Torque-free dynamics in the principal frame of the inertia tensor, written once over a
// lane type T (aloft/lanes/lanes.hpp): one simulation when T is float or double, several side
// by side when T is a SIMD register.
//
// In principal axes the tensor is diagonal, I = diag(I1, I2, I3), and Euler's equations
// I dw/dt = (I w) x w become
//   dw1/dt = c1 w2 w3,  dw2/dt = c2 w3 w1,  dw3/dt = c3 w1 w2,
//   c1 = (I2 - I3)/I1,  c2 = (I3 - I1)/I2,  c3 = (I1 - I2)/I3:
// six multiplies per evaluation instead of two full 3x3 products and a cross product.
// The orientation integrated here maps principal axes to world, q_p = q_body * A with A
// the principal axes (InertiaTensor::principal_axes()); aloft/dynamics/principal_frame.hpp
// converts states once on the way in and once per output sample.
// Kinematics as everywhere in aloft: dq/dt = 1/2 q * (0, w) (aloft/dynamics/rotation.hpp).
#pragma once

#include <cmath>

#include "aloft/lanes/lanes.hpp"

namespace aloft {

// Orientation (principal axes to world) and body rate in principal axes.
template <typename T>
struct PrincipalState {
  LaneQuat<T> q;
  LaneVec3<T> w;
};

// The c1, c2, c3 of Euler's equations above.
template <typename T>
struct EulerCoefficients {
  T c1, c2, c3;
};

template <typename T>
inline EulerCoefficients<T> euler_coefficients(const T& i1, const T& i2, const T& i3) {
  return {(i2 - i3) / i1, (i3 - i1) / i2, (i1 - i2) / i3};
}

// dw/dt in principal axes.
template <typename T>
inline LaneVec3<T> principal_angular_acceleration(const EulerCoefficients<T>& c, const LaneVec3<T>& w) {
  return {c.c1 * (w.y * w.z), c.c2 * (w.z * w.x), c.c3 * (w.x * w.y)};
}

namespace detail {

template <typename T>
inline LaneVec3<T> plus_scaled(const LaneVec3<T>& a, const T& s, const LaneVec3<T>& d) {
  return {a.x + s * d.x, a.y + s * d.y, a.z + s * d.z};
}

template <typename T>
inline LaneQuat<T> plus_scaled(const LaneQuat<T>& a, const T& s, const LaneQuat<T>& d) {
  return {a.w + s * d.w, a.x + s * d.x, a.y + s * d.y, a.z + s * d.z};
}

// 2 dq/dt = q * (0, w); the 1/2 is folded into the step sizes.
template <typename T>
inline LaneQuat<T> twice_quaternion_rate(const LaneQuat<T>& q, const LaneVec3<T>& w) {
  return {-(q.x * w.x + q.y * w.y + q.z * w.z), q.w * w.x + q.y * w.z - q.z * w.y,
          q.w * w.y + q.z * w.x - q.x * w.z, q.w * w.z + q.x * w.y - q.y * w.x};
}

// k1 + 2 k2 + 2 k3 + k4: the RK4 combination.
template <typename T>
inline LaneVec3<T> rk4_sum(const LaneVec3<T>& k1, const LaneVec3<T>& k2, const LaneVec3<T>& k3,
                           const LaneVec3<T>& k4) {
  const T two(LaneScalar<T>(2));
  return {k1.x + two * (k2.x + k3.x) + k4.x, k1.y + two * (k2.y + k3.y) + k4.y,
          k1.z + two * (k2.z + k3.z) + k4.z};
}

template <typename T>
inline LaneQuat<T> rk4_sum(const LaneQuat<T>& k1, const LaneQuat<T>& k2, const LaneQuat<T>& k3,
                           const LaneQuat<T>& k4) {
  const T two(LaneScalar<T>(2));
  return {k1.w + two * (k2.w + k3.w) + k4.w, k1.x + two * (k2.x + k3.x) + k4.x,
          k1.y + two * (k2.y + k3.y) + k4.y, k1.z + two * (k2.z + k3.z) + k4.z};
}

}  // namespace detail

// One classical RK4 step of the body rate alone, principal axes (h may be negative, and
// differ from lane to lane).
template <typename T>
inline LaneVec3<T> principal_rate_rk4_step(const EulerCoefficients<T>& c, const LaneVec3<T>& w0, const T& h) {
  const T half = T(LaneScalar<T>(0.5)) * h;
  const LaneVec3<T> k1 = principal_angular_acceleration(c, w0);
  const LaneVec3<T> k2 = principal_angular_acceleration(c, detail::plus_scaled(w0, half, k1));
  const LaneVec3<T> k3 = principal_angular_acceleration(c, detail::plus_scaled(w0, half, k2));
  const LaneVec3<T> k4 = principal_angular_acceleration(c, detail::plus_scaled(w0, h, k3));
  const T sixth = h * T(LaneScalar<T>(1) / LaneScalar<T>(6));
  return detail::plus_scaled(w0, sixth, detail::rk4_sum(k1, k2, k3, k4));
}

// Euler's coefficients times half a step, h/2 c: what one RK4 step of the rate needs of c
// and h together. Formed once per step for every simulation that takes it (the onboard
// check's K seeds all step by the same sample interval), it takes the three products by
// h/2 out of each stage of every simulation.
template <typename T>
inline EulerCoefficients<T> half_step_coefficients(const EulerCoefficients<T>& c, const T& h) {
  const T half = T(LaneScalar<T>(0.5)) * h;
  return {half * c.c1, half * c.c2, half * c.c3};
}

// The same RK4 step of the rate as principal_rate_rk4_step, from h/2 c
// (half_step_coefficients): each stage's increment is h/2 times its rate, so
// w_{n+1} = w0 + (k1 + 2 k2 + 2 k3 + k4) / 3. Equal to that step up to rounding; the
// host's batch simulations keep the other form, whose results their reports hold.
template <typename T>
inline LaneVec3<T> principal_rate_rk4_half_steps(const EulerCoefficients<T>& half_c, const LaneVec3<T>& w0) {
  const T two(LaneScalar<T>(2));
  const LaneVec3<T> k1 = principal_angular_acceleration(half_c, w0);
  const LaneVec3<T> k2 =
      principal_angular_acceleration(half_c, LaneVec3<T>{w0.x + k1.x, w0.y + k1.y, w0.z + k1.z});
  const LaneVec3<T> k3 =
      principal_angular_acceleration(half_c, LaneVec3<T>{w0.x + k2.x, w0.y + k2.y, w0.z + k2.z});
  const LaneVec3<T> k4 = principal_angular_acceleration(half_c, detail::plus_scaled(w0, two, k3));
  return detail::plus_scaled(w0, T(LaneScalar<T>(1) / LaneScalar<T>(3)), detail::rk4_sum(k1, k2, k3, k4));
}

// The increments (dq, dw) of one classical RK4 step of orientation and rate, before the
// quaternion is renormalised: q + dq, w + dw. Rk4Integrator::step rotates the increments
// rather than the whole state back into body axes, so the rounding of that rotation
// touches only the small part that changed.
template <typename T>
inline void principal_rk4_increments(const EulerCoefficients<T>& c, const PrincipalState<T>& s, const T& h,
                                     LaneQuat<T>& dq, LaneVec3<T>& dw) {
  using Scalar = LaneScalar<T>;
  const T half = T(Scalar(0.5)) * h;
  const T quarter = T(Scalar(0.25)) * h;  // half a step times the folded 1/2 of dq/dt
  const LaneQuat<T>& q0 = s.q;
  const LaneVec3<T>& w0 = s.w;

  const LaneVec3<T> k1w = principal_angular_acceleration(c, w0);
  const LaneQuat<T> k1q = detail::twice_quaternion_rate(q0, w0);
  const LaneVec3<T> w1 = detail::plus_scaled(w0, half, k1w);
  const LaneQuat<T> q1 = detail::plus_scaled(q0, quarter, k1q);

  const LaneVec3<T> k2w = principal_angular_acceleration(c, w1);
  const LaneQuat<T> k2q = detail::twice_quaternion_rate(q1, w1);
  const LaneVec3<T> w2 = detail::plus_scaled(w0, half, k2w);
  const LaneQuat<T> q2 = detail::plus_scaled(q0, quarter, k2q);

  const LaneVec3<T> k3w = principal_angular_acceleration(c, w2);
  const LaneQuat<T> k3q = detail::twice_quaternion_rate(q2, w2);
  const LaneVec3<T> w3 = detail::plus_scaled(w0, h, k3w);
  const LaneQuat<T> q3 = detail::plus_scaled(q0, half, k3q);

  const LaneVec3<T> k4w = principal_angular_acceleration(c, w3);
  const LaneQuat<T> k4q = detail::twice_quaternion_rate(q3, w3);

  const T sixth = h * T(Scalar(1) / Scalar(6));
  const T twelfth = h * T(Scalar(1) / Scalar(12));
  const LaneVec3<T> sw = detail::rk4_sum(k1w, k2w, k3w, k4w);
  const LaneQuat<T> sq = detail::rk4_sum(k1q, k2q, k3q, k4q);
  dw = {sixth * sw.x, sixth * sw.y, sixth * sw.z};
  dq = {twelfth * sq.w, twelfth * sq.x, twelfth * sq.y, twelfth * sq.z};
}

// q / |q|, lane-wise. One RK4 step leaves |q|^2 = 1 + e with e of the order of the
// step's truncation error (below 1e-10 at the steps aloft takes), so one Newton step
// for 1/sqrt from 1, (3 - |q|^2)/2 = 1/|q| (1 + O(e^2)), is exact to rounding and takes
// a multiply and an add instead of a square root and a division on the step's critical
// path. Lanes with |e| above 1e-4 (huge steps) take the square root.
template <typename T>
inline LaneQuat<T> normalized(const LaneQuat<T>& q) {
  using Scalar = LaneScalar<T>;
  using std::abs;
  using std::sqrt;
  const T norm_sq = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
  T inverse_norm = T(Scalar(1.5)) - T(Scalar(0.5)) * norm_sq;
  const auto far = abs(norm_sq - T(Scalar(1))) > T(Scalar(1e-4));
  if (any(far)) inverse_norm = select(far, T(Scalar(1)) / sqrt(norm_sq), inverse_norm);
  return {q.w * inverse_norm, q.x * inverse_norm, q.y * inverse_norm, q.z * inverse_norm};
}

// One classical RK4 step of orientation and rate, the quaternion renormalised after it.
template <typename T>
inline void principal_rk4_step(const EulerCoefficients<T>& c, PrincipalState<T>& s, const T& h) {
  LaneQuat<T> dq;
  LaneVec3<T> dw;
  principal_rk4_increments(c, s, h, dq, dw);
  s.w = {s.w.x + dw.x, s.w.y + dw.y, s.w.z + dw.z};
  s.q = normalized(LaneQuat<T>{s.q.w + dq.w, s.q.x + dq.x, s.q.y + dq.y, s.q.z + dq.z});
}

}  // namespace aloft
