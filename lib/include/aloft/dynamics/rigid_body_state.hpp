// The state of a torque-free rigid body: orientation (body to world) and angular
// velocity in body axes. Conventions: aloft/dynamics/rotation.hpp.
#pragma once

#include "aloft/dynamics/rotation.hpp"
#include "aloft/status.hpp"

namespace aloft {

template <typename Scalar>
struct RigidBodyState {
  Quat<Scalar> orientation = Quat<Scalar>::Identity();
  Vec3<Scalar> omega_body = Vec3<Scalar>::Zero();

  Vec3<Scalar> omega_world() const { return orientation * omega_body; }
};

// Direction of integration in time; steps are always given as positive durations.
enum class TimeDirection : signed char { forward = 1, backward = -1 };

// Checks a state before it is integrated: finite numbers and a unit quaternion.
template <typename Scalar>
inline Status validate(const RigidBodyState<Scalar>& s) {
  if (!all_finite(s.orientation) || !all_finite(s.omega_body)) return Status::non_finite_input;
  if (!is_unit(s.orientation)) return Status::non_unit_quaternion;
  return Status::ok;
}

// Checks a step known to be finite: strictly positive.
template <typename Scalar>
inline Status validate_finite_step(Scalar dt) {
  return dt > Scalar(0) ? Status::ok : Status::non_positive_time_step;
}

// Checks a step: finite and strictly positive.
template <typename Scalar>
inline Status validate_step(Scalar dt) {
  return std::isfinite(dt) ? validate_finite_step(dt) : Status::non_finite_input;
}

template <typename Scalar>
inline Scalar signed_step(Scalar dt, TimeDirection direction) {
  return direction == TimeDirection::forward ? dt : -dt;
}

// An integrator's checked step, the same for every integrator: advances `state` by dt
// (> 0) in `direction` through integrator.step_unchecked(state, h). On a bad step or
// state it returns the status and leaves `state` untouched.
template <typename Integrator, typename Scalar>
Status checked_step(const Integrator& integrator, RigidBodyState<Scalar>& state, Scalar dt,
                    TimeDirection direction) {
  Status s = validate_step(dt);
  if (s == Status::ok) s = validate(state);
  if (s != Status::ok) return s;
  integrator.step_unchecked(state, signed_step(dt, direction));
  return all_finite(state.orientation) ? Status::ok : Status::non_finite_input;
}

}  // namespace aloft
