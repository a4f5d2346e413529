// Euler's torque-free equations in body axes: I dw/dt = (I w) x w.
// (The quaternion kinematics, dq/dt = 1/2 q * (0, w), live with each integrator.)
#pragma once

#include "aloft/dynamics/inertia_tensor.hpp"
#include "aloft/dynamics/principal_frame.hpp"
#include "aloft/dynamics/rigid_body_state.hpp"

namespace aloft {

// dw/dt of body rate w, in body axes with the full tensor (the integrators work in the
// principal frame instead: aloft/dynamics/principal_dynamics.hpp).
template <typename Scalar>
inline Vec3<Scalar> angular_acceleration(const InertiaTensor<Scalar>& inertia,
                                         const Vec3<Scalar>& omega_body) {
  return inertia.inverse() * (inertia.tensor() * omega_body).cross(omega_body);
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
