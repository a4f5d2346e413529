// What the accuracy tests measure, shared by the tests (test_exact_tops.cpp,
// test_invariants.cpp) and the table that prints the measurements (accuracy_table.cpp,
// the "Accuracy" table of docs/accuracy-and-speed.md): the integrators against exact torque-free motions and
// their invariants, over 1 s at 1 kHz with |w| up to 15 rad/s.
#pragma once

#include <algorithm>
#include <cmath>

#include "aloft/dynamics/deviation.hpp"
#include "aloft/dynamics/rk4_integrator.hpp"
#include "aloft/dynamics/splitting_integrator.hpp"
#include "exact_tops.hpp"
#include "test_api.hpp"

namespace aloft_test {

using aloft::Quat;
using aloft::Vec3;

template <typename S>
aloft::InertiaTensor<S> principal_inertia(double i1, double i2, double i3,
                                          const Quat<double>& axes = Quat<double>::Identity()) {
  aloft::InertiaTensor<S> inertia;
  const aloft::Status s =
      aloft::InertiaTensor<S>::make_from_principal(Vec3<S>(S(i1), S(i2), S(i3)), axes.cast<S>(), inertia);
  ALOFT_REQUIRE(s == aloft::Status::ok);
  return inertia;
}

// Largest orientation error of RK4 against the symmetric top over 1 s at 1 kHz.
template <typename S, typename Integrator>
double symmetric_top_orientation_error(const aloft_test::SymmetricTop& top) {
  const Integrator integrator(principal_inertia<S>(top.it, top.it, top.i3));
  aloft::RigidBodyState<S> state;
  state.orientation = top.q0.cast<S>();
  state.omega_body = top.omega0.cast<S>();
  double worst = 0.0;
  const S dt = S(1e-3);
  for (int k = 1; k <= 1000; ++k) {
    ALOFT_REQUIRE(integrator.step(state, dt) == aloft::Status::ok);
    const double t = k * 1e-3;
    const double err = aloft::angle_between(state.orientation.template cast<double>(), top.orientation(t));
    if (err > worst) worst = err;
  }
  return worst;
}

// Largest direction error of body rate against the asymmetric top over 1 s at 1 kHz,
// in a body frame rotated away from the principal one (full tensor).
// `principal_loop`: as a hot loop does, into the principal frame once and out once per
// sample (Rk4Integrator::step_principal); otherwise Rk4Integrator::step on body states.
template <typename S>
double asymmetric_top_direction_error(const aloft_test::AsymmetricTop& top,
                                      const Quat<double>& principal_to_body, bool principal_loop) {
  const aloft::Rk4Integrator<S> integrator(principal_inertia<S>(top.i1, top.i2, top.i3, principal_to_body));
  aloft::RigidBodyState<S> state;
  state.omega_body = (principal_to_body * top.omega(0.0)).cast<S>();
  aloft::PrincipalState<S> principal = integrator.frame().to_principal(state);
  double worst = 0.0;
  for (int k = 1; k <= 1000; ++k) {
    if (principal_loop) {
      integrator.step_principal(principal, S(1e-3));
      state = integrator.frame().to_body(principal);
    } else {
      ALOFT_REQUIRE(integrator.step(state, S(1e-3)) == aloft::Status::ok);
    }
    const Vec3<double> exact = principal_to_body * top.omega(k * 1e-3);
    const double err = aloft::deviation_angle<double>(state.omega_body.template cast<double>(), exact);
    if (err > worst) worst = err;
  }
  return worst;
}

inline const aloft_test::SymmetricTop kCylinderTops[] = {
    // The GF cylinder of the study, spun about a generic axis.
    {0.0183892, 0.0210806, Vec3<double>(3.0, -4.0, 12.0), aloft::quat_wxyz(0.9, 0.1, -0.3, 0.3).normalized()},
    // A flat disc, fast and mostly transverse: the hardest of the set for RK4.
    {0.5, 1.0, Vec3<double>(10.0, 8.0, 7.0), Quat<double>::Identity()},
    // A long rod-like top (axial moment smaller than transverse).
    {1.0, 0.2, Vec3<double>(1.0, 2.0, 14.0), aloft::quat_wxyz(0.0, 1.0, 0.0, 0.0)},
};

// Near the separatrix (k^2 = 0.999): w2 hangs near +-B and flips quickly; t_offset puts
// a flip inside the simulated second.
inline aloft_test::AsymmetricTop flipping_top() {
  aloft_test::AsymmetricTop top{0.01, 0.02, 0.03, 0.0, 5.0, 0.0};
  top.a = top.c * std::sqrt(0.999 * (top.i3 - top.i2) * top.i3 / ((top.i2 - top.i1) * top.i1));
  top.t_offset = top.flip_interval() - 0.5;  // the next flip is at t = 0.5 s
  return top;
}

// An asymmetric body in a tilted frame (full tensor), tumbling near the intermediate axis.
inline aloft::InertiaTensor<double> tumbling_body() {
  aloft::InertiaTensor<double> inertia;
  const aloft::Status s = aloft::InertiaTensor<double>::make_from_principal(
      Vec3<double>(0.012, 0.021, 0.030), aloft::quat_wxyz(0.9, 0.3, -0.2, 0.1).normalized(), inertia);
  ALOFT_REQUIRE(s == aloft::Status::ok);
  return inertia;
}

inline aloft::RigidBodyState<double> tumbling_start(const aloft::InertiaTensor<double>& inertia) {
  aloft::RigidBodyState<double> state;
  state.orientation = aloft::quat_wxyz(0.5, 0.5, -0.5, 0.5);
  // Mostly about the intermediate principal axis, with a small perturbation.
  const Quat<double> axes = inertia.principal_axes();
  state.omega_body = axes * Vec3<double>(0.3, 14.0, 0.4);
  return state;
}

struct Drift {
  double energy = 0.0;
  double momentum = 0.0;
};

template <typename Integrator>
Drift invariant_drift(const Integrator& integrator, aloft::RigidBodyState<double> state) {
  const aloft::InertiaTensor<double>& inertia = integrator.inertia();
  const double e0 = inertia.kinetic_energy(state.omega_body);
  const Vec3<double> l0 = state.orientation * inertia.angular_momentum(state.omega_body);
  Drift worst;
  for (int k = 0; k < 1000; ++k) {
    ALOFT_REQUIRE(integrator.step(state, 1e-3) == aloft::Status::ok);
    const double e = inertia.kinetic_energy(state.omega_body);
    const double l = inertia.angular_momentum(state.omega_body).norm();
    worst.energy = std::max(worst.energy, std::abs(e - e0) / e0);
    worst.momentum = std::max(worst.momentum, std::abs(l - l0.norm()) / l0.norm());
  }
  return worst;
}

template <typename Integrator>
double round_trip_error(const Integrator& integrator, const aloft::RigidBodyState<double>& start,
                        double* rate_error) {
  aloft::RigidBodyState<double> state = start;
  for (int k = 0; k < 1000; ++k) {
    ALOFT_REQUIRE(integrator.step(state, 1e-3, aloft::TimeDirection::forward) == aloft::Status::ok);
  }
  for (int k = 0; k < 1000; ++k) {
    ALOFT_REQUIRE(integrator.step(state, 1e-3, aloft::TimeDirection::backward) == aloft::Status::ok);
  }
  *rate_error = (state.omega_body - start.omega_body).norm() / start.omega_body.norm();
  return aloft::angle_between(state.orientation, start.orientation);
}

}  // namespace aloft_test
