// A structure-preserving integrator for the torque-free body: the Hamiltonian
// H = sum_i m_i^2 / (2 I_i) (m: angular momentum in principal axes) is split into its
// three terms, each of which is solved exactly by a rotation about one principal axis:
// the body turns by theta = m_i/I_i * h about axis i and m turns by -theta with it.
// Every sub-step is an exact rotation, so |L| is conserved to rounding, and the
// symmetric composition X(h/2) Y(h/2) Z(h) Y(h/2) X(h/2) is time-reversible and
// symplectic (energy error bounded, no drift). Yoshida's triple jump raises the
// symmetric second-order step to fourth order.
//
// Reference: McLachlan, "Explicit Lie-Poisson integration and the Euler equations",
// Phys. Rev. Lett. 71 (1993); Yoshida, Phys. Lett. A 150 (1990).
#pragma once

#include "aloft/dynamics/inertia_tensor.hpp"
#include "aloft/dynamics/rigid_body_state.hpp"

namespace aloft {

template <typename Scalar>
class SplittingIntegrator {
 public:
  enum class Order : unsigned char { second = 2, fourth = 4 };

  explicit SplittingIntegrator(const InertiaTensor<Scalar>& inertia, Order order = Order::fourth)
      : inertia_(inertia),
        order_(order),
        to_body_(inertia.principal_axes()),
        to_body_matrix_(inertia.principal_axes().toRotationMatrix()) {}

  const InertiaTensor<Scalar>& inertia() const { return inertia_; }

  Status step(RigidBodyState<Scalar>& state, Scalar dt,
              TimeDirection direction = TimeDirection::forward) const {
    return checked_step(*this, state, dt, direction);
  }

  void step_unchecked(RigidBodyState<Scalar>& state, Scalar h) const {
    // Work in principal axes: orientation principal->world and momentum m = I_p w_p.
    Quat<Scalar> q = state.orientation * to_body_;
    const Vec3<Scalar>& moments = inertia_.principal_moments();
    Vec3<Scalar> m = moments.cwiseProduct(to_body_matrix_.transpose() * state.omega_body);
    if (order_ == Order::second) {
      strang(q, m, h);
    } else {
      // Yoshida: weights w1, w0, w1 with 2 w1 + w0 = 1 and 2 w1^3 + w0^3 = 0.
      const Scalar cbrt2 = Scalar(1.2599210498948731647672106);
      const Scalar w1 = Scalar(1) / (Scalar(2) - cbrt2);
      const Scalar w0 = -cbrt2 * w1;
      strang(q, m, w1 * h);
      strang(q, m, w0 * h);
      strang(q, m, w1 * h);
    }
    q.normalize();
    state.orientation = q * to_body_.conjugate();
    state.omega_body = to_body_matrix_ * m.cwiseQuotient(moments);
  }

 private:
  void strang(Quat<Scalar>& q, Vec3<Scalar>& m, Scalar h) const {
    const Scalar half = Scalar(0.5) * h;
    flow(0, half, q, m);
    flow(1, half, q, m);
    flow(2, h, q, m);
    flow(1, half, q, m);
    flow(0, half, q, m);
  }

  // Exact flow of H_i = m_i^2 / (2 I_i) for time h: rotation about principal axis i.
  void flow(int axis, Scalar h, Quat<Scalar>& q, Vec3<Scalar>& m) const {
    const Scalar theta = m(axis) / inertia_.principal_moments()(axis) * h;
    const Scalar c = std::cos(theta);
    const Scalar s = std::sin(theta);
    const int a = (axis + 1) % 3;
    const int b = (axis + 2) % 3;
    // m <- R_axis(-theta) m
    const Scalar ma = m(a);
    const Scalar mb = m(b);
    m(a) = c * ma + s * mb;
    m(b) = -s * ma + c * mb;
    // q <- q * exp(theta/2 e_axis)
    const Scalar hc = std::cos(Scalar(0.5) * theta);
    const Scalar hs = std::sin(Scalar(0.5) * theta);
    Quat<Scalar> r(hc, Scalar(0), Scalar(0), Scalar(0));
    r.coeffs()(axis) = hs;
    q = q * r;
  }

  InertiaTensor<Scalar> inertia_;
  Order order_;
  Quat<Scalar> to_body_;
  Mat3<Scalar> to_body_matrix_;
};

}  // namespace aloft
