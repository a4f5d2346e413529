// Conservation of energy and angular momentum, and time reversal: forward then
// backward over the same span returns to the start.
#include "accuracy_measures.hpp"
#include "test_api.hpp"
#include "tolerances.hpp"

using aloft::Vec3;
using aloft_test::Drift;
using aloft_test::invariant_drift;
using aloft_test::round_trip_error;
using aloft_test::tumbling_body;
using aloft_test::tumbling_start;
using Accuracy = aloft_test::Accuracy<double>;

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
