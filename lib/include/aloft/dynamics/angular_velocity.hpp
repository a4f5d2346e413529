// Angular velocity from two consecutive orientations (Euler's rotation theorem): the
// axis-angle of the relative rotation divided by the time between them. Exact for a
// constant rate; for a varying rate it is the rate of the mean rotation over dt. The
// log map keeps full precision for tiny angles (aloft/dynamics/rotation.hpp).
#pragma once

#include "aloft/dynamics/rigid_body_state.hpp"

namespace aloft {

// Body axes: log(q_k^-1 q_{k+1}) / dt, what a body-mounted gyro reports (SPEC §1).
template <typename Scalar>
inline Status omega_body_from_orientations(const Quat<Scalar>& q_k, const Quat<Scalar>& q_next, Scalar dt,
                                           Vec3<Scalar>& omega_out) {
  Status s = validate_step(dt);
  if (s != Status::ok) return s;
  if (!is_unit(q_k) || !is_unit(q_next)) {
    return (all_finite(q_k) && all_finite(q_next)) ? Status::non_unit_quaternion : Status::non_finite_input;
  }
  omega_out = quat_log(Quat<Scalar>(q_k.conjugate() * q_next)) / dt;
  return Status::ok;
}

// World axes: log(q_{k+1} q_k^-1) / dt.
template <typename Scalar>
inline Status omega_world_from_orientations(const Quat<Scalar>& q_k, const Quat<Scalar>& q_next, Scalar dt,
                                            Vec3<Scalar>& omega_out) {
  Status s = validate_step(dt);
  if (s != Status::ok) return s;
  if (!is_unit(q_k) || !is_unit(q_next)) {
    return (all_finite(q_k) && all_finite(q_next)) ? Status::non_unit_quaternion : Status::non_finite_input;
  }
  omega_out = quat_log(Quat<Scalar>(q_next * q_k.conjugate())) / dt;
  return Status::ok;
}

}  // namespace aloft
