// Classical fourth-order Runge-Kutta on (q, w) for the torque-free body, with the
// quaternion renormalised after every step. Accurate and cheap; it conserves energy
// and |L| only to its truncation error (see SplittingIntegrator for exact |L|).
#pragma once

#include "aloft/euler_equations.hpp"

namespace aloft {

template <typename Scalar>
class Rk4Integrator {
 public:
  explicit Rk4Integrator(const InertiaTensor<Scalar>& inertia) : inertia_(inertia) {}

  const InertiaTensor<Scalar>& inertia() const { return inertia_; }

  // Advances `state` by dt (> 0) in `direction`. On a bad step or state it returns the
  // status and leaves `state` untouched.
  Status step(RigidBodyState<Scalar>& state, Scalar dt,
              TimeDirection direction = TimeDirection::forward) const {
    Status s = validate_step(dt);
    if (s == Status::ok) s = validate(state);
    if (s != Status::ok) return s;
    step_unchecked(state, signed_step(dt, direction));
    return all_finite(state.orientation) ? Status::ok : Status::non_finite_input;
  }

  // The step itself, for hot loops that validated their inputs once (h may be negative).
  void step_unchecked(RigidBodyState<Scalar>& state, Scalar h) const {
    using Vec4 = Eigen::Matrix<Scalar, 4, 1>;
    const Scalar half = Scalar(0.5) * h;
    const Vec4 q0 = state.orientation.coeffs();  // Eigen storage order x, y, z, w
    const Vec3<Scalar>& w0 = state.omega_body;

    const Vec3<Scalar> k1w = angular_acceleration(inertia_, w0);
    const Vec4 k1q = rate(q0, w0);
    const Vec3<Scalar> w1 = w0 + half * k1w;
    const Vec4 q1 = q0 + half * k1q;

    const Vec3<Scalar> k2w = angular_acceleration(inertia_, w1);
    const Vec4 k2q = rate(q1, w1);
    const Vec3<Scalar> w2 = w0 + half * k2w;
    const Vec4 q2 = q0 + half * k2q;

    const Vec3<Scalar> k3w = angular_acceleration(inertia_, w2);
    const Vec4 k3q = rate(q2, w2);
    const Vec3<Scalar> w3 = w0 + h * k3w;
    const Vec4 q3 = q0 + h * k3q;

    const Vec3<Scalar> k4w = angular_acceleration(inertia_, w3);
    const Vec4 k4q = rate(q3, w3);

    const Scalar sixth = h / Scalar(6);
    state.omega_body = w0 + sixth * (k1w + Scalar(2) * (k2w + k3w) + k4w);
    Vec4 q = q0 + sixth * (k1q + Scalar(2) * (k2q + k3q) + k4q);
    q /= q.norm();
    state.orientation.coeffs() = q;
  }

 private:
  // dq/dt in Eigen's coefficient order (x, y, z, w), avoiding quaternion temporaries.
  static Eigen::Matrix<Scalar, 4, 1> rate(const Eigen::Matrix<Scalar, 4, 1>& q,
                                          const Vec3<Scalar>& w) {
    const Scalar qx = q(0), qy = q(1), qz = q(2), qw = q(3);
    const Scalar h = Scalar(0.5);
    return Eigen::Matrix<Scalar, 4, 1>(h * (qw * w.x() + qy * w.z() - qz * w.y()),
                                       h * (qw * w.y() + qz * w.x() - qx * w.z()),
                                       h * (qw * w.z() + qx * w.y() - qy * w.x()),
                                       h * (-qx * w.x() - qy * w.y() - qz * w.z()));
  }

  InertiaTensor<Scalar> inertia_;
};

}  // namespace aloft
