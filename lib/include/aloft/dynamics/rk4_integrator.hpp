// Classical fourth-order Runge-Kutta on (q, w) for the torque-free body, with the
// quaternion renormalised after every step, taken in the principal frame of the tensor
// (aloft/dynamics/principal_dynamics.hpp: a diagonal tensor, six multiplies per evaluation).
// Accurate and cheap; it conserves energy and |L| only to its truncation error (see
// SplittingIntegrator for exact |L|).
#pragma once

#include "aloft/dynamics/euler_equations.hpp"

namespace aloft {

template <typename Scalar>
class Rk4Integrator {
 public:
  explicit Rk4Integrator(const InertiaTensor<Scalar>& inertia) : inertia_(inertia), frame_(inertia) {}

  const InertiaTensor<Scalar>& inertia() const { return inertia_; }

  // Advances `state` by dt (> 0) in `direction`. On a bad step or state it returns the
  // status and leaves `state` untouched.
  Status step(RigidBodyState<Scalar>& state, Scalar dt,
              TimeDirection direction = TimeDirection::forward) const {
    return checked_step(*this, state, dt, direction);
  }

  // The step itself, for loops that validated their inputs once (h may be negative):
  // the RK4 increments in the principal frame, rotated back into body axes and added to
  // the body state. (Rotating the whole state there and back at every step would let
  // the rounding of the rotation, 1e-7 in float, build up over thousands of steps.)
  void step_unchecked(RigidBodyState<Scalar>& state, Scalar h) const {
    LaneQuat<Scalar> dq;
    LaneVec3<Scalar> dw;
    principal_rk4_increments(frame_.coefficients(), frame_.to_principal(state), h, dq, dw);
    state.omega_body += frame_.rate_to_body(dw);
    const Quat<Scalar> dq_body = quat_wxyz(dq.w, dq.x, dq.y, dq.z) * frame_.to_body().conjugate();
    state.orientation.coeffs() += dq_body.coeffs();
    state.orientation.normalize();
  }

  // Hot loops that take many steps convert once (frame().to_principal) and step here,
  // converting back only for the samples they output.
  const PrincipalFrame<Scalar>& frame() const { return frame_; }
  void step_principal(PrincipalState<Scalar>& state, Scalar h) const {
    principal_rk4_step(frame_.coefficients(), state, h);
  }

 private:
  InertiaTensor<Scalar> inertia_;
  PrincipalFrame<Scalar> frame_;
};

}  // namespace aloft
