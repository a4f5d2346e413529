// Euler's equations in body axes: torque-free, I dw/dt = (I w) x w; with a rotor whose
// momentum relative to the body is h (aloft/dynamics/rotor.hpp, SPEC §2),
//   I dw/dt + w x (I w + h) = -dh/dt;
// and the same integrated over an interval [t_a, t_b], which needs no derivative of a
// measured rate (the tensor estimate, aloft/onboard/tensor_estimator.hpp):
//   I (w_b - w_a) + ∫ w x (I w) dt + (h_b - h_a) + ∫ w x h dt = 0.
// (The quaternion kinematics, dq/dt = 1/2 q * (0, w), live with each integrator.)
#pragma once

#include "aloft/dynamics/inertia_tensor.hpp"
#include "aloft/dynamics/principal_frame.hpp"
#include "aloft/dynamics/rigid_body_state.hpp"
#include "aloft/dynamics/rotor.hpp"

namespace aloft {

// dw/dt of body rate w, in body axes with the full tensor (the integrators work in the
// principal frame instead: aloft/dynamics/principal_dynamics.hpp).
template <typename Scalar>
inline Vec3<Scalar> angular_acceleration(const InertiaTensor<Scalar>& inertia,
                                         const Vec3<Scalar>& omega_body) {
  return inertia.inverse() * (inertia.tensor() * omega_body).cross(omega_body);
}

// dw/dt with a rotor's momentum h and its rate dh/dt (body axes).
template <typename Scalar>
inline Vec3<Scalar> angular_acceleration(const InertiaTensor<Scalar>& inertia, const Vec3<Scalar>& omega_body,
                                         const Vec3<Scalar>& h, const Vec3<Scalar>& h_dot) {
  return inertia.inverse() * ((inertia.tensor() * omega_body + h).cross(omega_body) - h_dot);
}

// ∫ w x (I w) dt from P = ∫ w w^T dt alone: (w x I w)_i = e_ijk w_j (I w)_k = e_ijk M_kj
// with M = I P, so (w x I w)_x = M(2,1) - M(1,2) and its cyclic turns. The tensor enters
// linearly and the rate only through P, so a stream of rates needs only P's six sums.
template <typename Scalar>
inline Vec3<Scalar> integrated_gyroscopic_torque(const Mat3<Scalar>& inertia, const Mat3<Scalar>& p) {
  const Mat3<Scalar> m = inertia * p;
  return Vec3<Scalar>(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1));
}

// The body's side of the integrated equations, I (w_b - w_a) + ∫ w x (I w) dt: zero over
// any interval of torque-free flight.
template <typename Scalar>
inline Vec3<Scalar> integrated_body_torque(const Mat3<Scalar>& inertia, const Vec3<Scalar>& delta_omega,
                                           const Mat3<Scalar>& p) {
  return inertia * delta_omega + integrated_gyroscopic_torque(inertia, p);
}

// The same as a linear map of the tensor's six entries (xx yy zz xy xz yz): column m is
// integrated_body_torque(E_m, delta_omega, p) for the m-th unit tensor E_m (1 at (i, j) and
// (j, i)). With E_m w = e_i w_j + e_j w_i, its gyroscopic part integrates to
// P e_j x e_i + P e_i x e_j (one term when i = j): entries of P, no product of tensors
// (tests/core/test_tensor_estimator.cpp checks each column against the line above).
template <typename Scalar>
inline Eigen::Matrix<Scalar, 3, 6> integrated_body_torque_per_entry(const Vec3<Scalar>& d,
                                                                    const Mat3<Scalar>& p) {
  const Scalar xx = p(0, 0), yy = p(1, 1), zz = p(2, 2), xy = p(0, 1), xz = p(0, 2), yz = p(1, 2);
  Eigen::Matrix<Scalar, 3, 6> a;
  a << d.x(), -yz, yz, d.y() - xz, d.z() + xy, yy - zz,  //
      xz, d.y(), -xz, d.x() + yz, zz - xx, d.z() - xy,   //
      -xy, xy, d.z(), xx - yy, d.x() - yz, d.y() + xz;
  return a;
}

// The rotor's side, (h_b - h_a) + ∫ w x h dt with h = J s axis: from the change of its
// speed s and S = ∫ s w dt.
template <typename Scalar>
inline Vec3<Scalar> integrated_rotor_torque(const Rotor<Scalar>& rotor, Scalar delta_speed,
                                            const Vec3<Scalar>& speed_omega_integral) {
  return rotor.inertia_kg_m2 * (delta_speed * rotor.axis + speed_omega_integral.cross(rotor.axis));
}

// How the integrated equations' residual, body + rotor side, moves when the gyro reads each
// axis k a fraction d_k too high (w -> D w, D = diag(1 + d)): column k is its derivative
// in d_k at d = 0. Under D the rate's change goes to D Δw, P to D P D and S = ∫ s w dt to
// D S, so with P_k = P e_k
//   I e_k Δw_k + e_k x (I P_k) + P_k x (I e_k) + J S_k (e_k x axis),
// linear in the tensor and needing nothing but the piece's integrals
// (tests/core/test_tensor_estimator.cpp checks it against a central difference).
template <typename Scalar>
inline Mat3<Scalar> integrated_torque_gyro_scale_sensitivity(const Mat3<Scalar>& inertia,
                                                             const Vec3<Scalar>& delta_omega,
                                                             const Mat3<Scalar>& p,
                                                             const Rotor<Scalar>& rotor,
                                                             const Vec3<Scalar>& speed_omega_integral) {
  Mat3<Scalar> g;
  for (int k = 0; k < 3; ++k) {
    const Vec3<Scalar> e = Vec3<Scalar>::Unit(k), pk = p.col(k), ie = inertia.col(k);
    g.col(k) = ie * delta_omega(k) + e.cross(inertia * pk) + pk.cross(ie) +
               (rotor.inertia_kg_m2 * speed_omega_integral(k)) * e.cross(rotor.axis);
  }
  return g;
}

// One classical RK4 step of the body rate alone (h may be negative), in body axes.
// Torque-free body rates evolve independently of orientation, so a gyro check that
// compares rates in body axes needs nothing more. Steps in the principal frame and
// rotates back; loops that take many steps keep the rate in principal axes instead
// (aloft/dynamics/principal_dynamics.hpp, as the onboard check does).
template <typename Scalar>
inline Vec3<Scalar> body_rate_rk4_step(const InertiaTensor<Scalar>& inertia, const Vec3<Scalar>& omega_body,
                                       Scalar h) {
  const PrincipalFrame<Scalar> frame(inertia);
  const Vec3<Scalar> w = frame.rate_to_principal(omega_body);
  return frame.rate_to_body(
      principal_rate_rk4_step(frame.coefficients(), LaneVec3<Scalar>{w.x(), w.y(), w.z()}, h));
}

}  // namespace aloft
