// Euler's torque-free equations in body axes: I dw/dt = (I w) x w.
// (The quaternion kinematics, dq/dt = 1/2 q * (0, w), live with each integrator.)
#pragma once

#include "aloft/inertia_tensor.hpp"
#include "aloft/rigid_body_state.hpp"

namespace aloft {

// dw/dt of body rate w.
template <typename Scalar>
inline Vec3<Scalar> angular_acceleration(const InertiaTensor<Scalar>& inertia,
                                         const Vec3<Scalar>& omega_body) {
  return inertia.inverse() * (inertia.tensor() * omega_body).cross(omega_body);
}

// One classical RK4 step of the body rate alone (h may be negative). Torque-free body
// rates evolve independently of orientation, so a gyro check that compares rates in
// body axes needs nothing more; the onboard check uses this to stay cheap.
template <typename Scalar>
inline Vec3<Scalar> body_rate_rk4_step(const InertiaTensor<Scalar>& inertia,
                                       const Vec3<Scalar>& omega_body, Scalar h) {
  const Scalar half = Scalar(0.5) * h;
  const Vec3<Scalar> k1 = angular_acceleration(inertia, omega_body);
  const Vec3<Scalar> k2 = angular_acceleration(inertia, Vec3<Scalar>(omega_body + half * k1));
  const Vec3<Scalar> k3 = angular_acceleration(inertia, Vec3<Scalar>(omega_body + half * k2));
  const Vec3<Scalar> k4 = angular_acceleration(inertia, Vec3<Scalar>(omega_body + h * k3));
  return omega_body + (h / Scalar(6)) * (k1 + Scalar(2) * (k2 + k3) + k4);
}

}  // namespace aloft
