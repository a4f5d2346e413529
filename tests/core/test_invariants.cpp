// Conservation of energy and angular momentum, and time reversal: forward then
// backward over the same span returns to the start.
#include <algorithm>

#include "aloft/rk4_integrator.hpp"
#include "aloft/splitting_integrator.hpp"
#include "test_api.hpp"
#include "tolerances.hpp"

namespace {

using aloft::Quat;
using aloft::Vec3;
using Accuracy = aloft_test::Accuracy<double>;

// An asymmetric body in a tilted frame (full tensor), tumbling near the intermediate axis.
aloft::InertiaTensor<double> tumbling_body() {
  aloft::InertiaTensor<double> inertia;
  const aloft::Status s = aloft::InertiaTensor<double>::make_from_principal(
      Vec3<double>(0.012, 0.021, 0.030), aloft::quat_wxyz(0.9, 0.3, -0.2, 0.1).normalized(),
      inertia);
  ALOFT_REQUIRE(s == aloft::Status::ok);
  return inertia;
}

aloft::RigidBodyState<double> tumbling_start(const aloft::InertiaTensor<double>& inertia) {
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
    ALOFT_REQUIRE(integrator.step(state, 1e-3, aloft::TimeDirection::backward) ==
                  aloft::Status::ok);
  }
  *rate_error = (state.omega_body - start.omega_body).norm() / start.omega_body.norm();
  return aloft::angle_between(state.orientation, start.orientation);
}

}  // namespace

ALOFT_TEST_CASE("RK4 keeps energy and |L| over a tumbling second", "[invariants]") {
  const aloft::InertiaTensor<double> inertia = tumbling_body();
  const Drift drift = invariant_drift(aloft::Rk4Integrator<double>(inertia), tumbling_start(inertia));
  ALOFT_CHECK(drift.energy < Accuracy::rk4_invariant_drift);
  ALOFT_CHECK(drift.momentum < Accuracy::rk4_invariant_drift);
}

ALOFT_TEST_CASE("splitting keeps |L| to rounding and energy bounded", "[invariants]") {
  const aloft::InertiaTensor<double> inertia = tumbling_body();
  using Order = aloft::SplittingIntegrator<double>::Order;
  for (Order order : {Order::second, Order::fourth}) {
    const Drift drift =
        invariant_drift(aloft::SplittingIntegrator<double>(inertia, order), tumbling_start(inertia));
    ALOFT_CHECK(drift.momentum < Accuracy::splitting_momentum_drift);
    ALOFT_CHECK(drift.energy < (order == Order::second ? Accuracy::splitting2_energy_drift
                                                        : Accuracy::splitting4_energy_drift));
  }
}

ALOFT_TEST_CASE("the world angular momentum stays fixed", "[invariants]") {
  const aloft::InertiaTensor<double> inertia = tumbling_body();
  aloft::RigidBodyState<double> state = tumbling_start(inertia);
  const Vec3<double> l0 = state.orientation * inertia.angular_momentum(state.omega_body);
  const aloft::SplittingIntegrator<double> integrator(inertia);
  for (int k = 0; k < 1000; ++k) ALOFT_REQUIRE(integrator.step(state, 1e-3) == aloft::Status::ok);
  const Vec3<double> l1 = state.orientation * inertia.angular_momentum(state.omega_body);
  ALOFT_CHECK((l1 - l0).norm() / l0.norm() < 1e-6);
}

ALOFT_TEST_CASE("forward then backward returns to the start", "[invariants]") {
  const aloft::InertiaTensor<double> inertia = tumbling_body();
  const aloft::RigidBodyState<double> start = tumbling_start(inertia);
  double rate_error = 0.0;
  ALOFT_CHECK(round_trip_error(aloft::Rk4Integrator<double>(inertia), start, &rate_error) <
              Accuracy::rk4_round_trip);
  ALOFT_CHECK(rate_error < Accuracy::rk4_round_trip);
  ALOFT_CHECK(round_trip_error(aloft::SplittingIntegrator<double>(inertia), start, &rate_error) <
              Accuracy::splitting_round_trip);
  ALOFT_CHECK(rate_error < Accuracy::splitting_round_trip);
}
