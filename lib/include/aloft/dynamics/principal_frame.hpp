// The principal frame of one inertia tensor: the Euler coefficients of its principal
// moments and the fixed rotation A between principal and body axes
// (InertiaTensor::principal_axes(): column i of R(A) is principal axis i in body axes).
// States cross it once on the way in and once per output sample:
//   q_principal = q_body * A,   w_principal = R(A)^T w_body,   and back.
#pragma once

#include "aloft/dynamics/inertia_tensor.hpp"
#include "aloft/dynamics/principal_dynamics.hpp"
#include "aloft/dynamics/rigid_body_state.hpp"

namespace aloft {

template <typename Scalar>
class PrincipalFrame {
 public:
  PrincipalFrame() : PrincipalFrame(InertiaTensor<Scalar>()) {}
  explicit PrincipalFrame(const InertiaTensor<Scalar>& inertia)
      : coefficients_(euler_coefficients(inertia.principal_moments().x(), inertia.principal_moments().y(),
                                         inertia.principal_moments().z())),
        to_body_(inertia.principal_axes()),
        to_body_matrix_(inertia.principal_axes().toRotationMatrix()) {}

  const EulerCoefficients<Scalar>& coefficients() const { return coefficients_; }
  // A: principal axes into body axes, as a quaternion and as a matrix.
  const Quat<Scalar>& to_body() const { return to_body_; }
  const Mat3<Scalar>& to_body_matrix() const { return to_body_matrix_; }

  Vec3<Scalar> rate_to_principal(const Vec3<Scalar>& w_body) const {
    return to_body_matrix_.transpose() * w_body;
  }
  Vec3<Scalar> rate_to_body(const LaneVec3<Scalar>& w) const {
    return to_body_matrix_ * Vec3<Scalar>(w.x, w.y, w.z);
  }

  PrincipalState<Scalar> to_principal(const RigidBodyState<Scalar>& s) const {
    const Quat<Scalar> q = s.orientation * to_body_;
    const Vec3<Scalar> w = rate_to_principal(s.omega_body);
    return {{q.w(), q.x(), q.y(), q.z()}, {w.x(), w.y(), w.z()}};
  }
  RigidBodyState<Scalar> to_body(const PrincipalState<Scalar>& s) const {
    RigidBodyState<Scalar> out;
    out.orientation = quat_wxyz(s.q.w, s.q.x, s.q.y, s.q.z) * to_body_.conjugate();
    out.omega_body = rate_to_body(s.w);
    return out;
  }

 private:
  EulerCoefficients<Scalar> coefficients_;
  Quat<Scalar> to_body_;
  Mat3<Scalar> to_body_matrix_;
};

}  // namespace aloft
