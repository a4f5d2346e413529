// Issue 9: a non-uniform gyro scale mimics wrong inertia moments exactly when the nominal
// moments are distinct and the wrong ones keep their order (the gyro reading the principal
// axes), and never on a body of revolution whose moments lose their symmetry. The truth
// is thrown by the generator's own integrator (independent of the diagnosis's model).
#include <catch2/catch.hpp>

#include <cmath>

#include "diagnose/3_fit/effect_fit.hpp"
#include "diagnose/3_fit/held_out.hpp"
#include "diagnose/2_model/moment_scale_equivalence.hpp"
#include "generator/perturbed_rigid_body.hpp"

using namespace aloft::host::diagnose;

namespace {

// Readings of a torque-free body with principal moments `truth` (body axes = principal
// axes), 1 kHz for 1 s, noise-free, each scaled by (1 + scale).
Flight thrown(const Eigen::Vector3d& truth, const Eigen::Vector3d& scale) {
  aloft::generator::FlightPhysics physics;
  physics.inertia_kg_m2 = truth.asDiagonal();
  const aloft::generator::PerturbedRigidBody body(physics);
  aloft::generator::FlightState start;
  start.omega_body = Eigen::Vector3d(4.0, -6.0, 7.0);
  Flight flight;
  for (int k = 0; k <= 1000; ++k) flight.time_s.push_back(k * 1e-3);
  for (const auto& s : body.sample(start, flight.time_s)) {
    flight.omega.push_back((Eigen::Vector3d::Ones() + scale).cwiseProduct(s.omega_body));
  }
  flight.usable.assign(flight.size(), 1);
  return flight;
}

// RMS of the readings' misfit (rad/s) when `effect` is fitted with the nominal moments.
double misfit(const Flight& flight, const Eigen::Vector3d& nominal_moments, Effect effect) {
  const NominalInertia nominal = NominalInertia::of_tensor(nominal_moments.asDiagonal());
  const FlightData data{&flight, all_samples(flight.size()), Eigen::Vector3d::Ones()};
  const EffectFit none = fit_effect(Effect::none, nominal, {data}, nullptr);
  const EffectFit fit = effect == Effect::none ? none : fit_effect(effect, nominal, {data}, &none);
  return std::sqrt(fit.cost / fit.residual_count);
}

}  // namespace

TEST_CASE("a gyro scale reproduces distinct moments that keep their order, exactly", "[equivalence]") {
  const Eigen::Vector3d nominal(0.0017, 0.0042, 0.0054);
  const Eigen::Vector3d wrong(0.0019, 0.0040, 0.0056);  // same order, each off by 4-12 %
  const auto scale = scale_mimicking_moments(nominal, wrong);
  REQUIRE(scale.has_value());
  // The scaled readings of the nominal body are the readings of the wrong one.
  const Flight truth = thrown(wrong, Eigen::Vector3d::Zero());
  // The nominal body started where the scaled gyro reads the true start rate.
  double worst = 0.0;
  {
    aloft::generator::FlightPhysics physics;
    physics.inertia_kg_m2 = nominal.asDiagonal();
    const aloft::generator::PerturbedRigidBody body(physics);
    aloft::generator::FlightState start;
    start.omega_body = truth.omega.front().cwiseQuotient(Eigen::Vector3d::Ones() + *scale);
    const auto states = body.sample(start, truth.time_s);
    for (std::size_t k = 0; k < states.size(); ++k) {
      const Eigen::Vector3d read = (Eigen::Vector3d::Ones() + *scale).cwiseProduct(states[k].omega_body);
      worst = std::max(worst, (read - truth.omega[k]).norm());
    }
  }
  CHECK(worst < 1e-6);
  // The diagnosis's own fit finds it: a scale fitted to the wrong body's readings leaves
  // nothing, while the nominal model misses by far more.
  CHECK(misfit(truth, nominal, Effect::gyro_scale) < 1e-5);
  CHECK(misfit(truth, nominal, Effect::none) > 1e-2);
}

TEST_CASE("no scale reproduces moments that change their order", "[equivalence]") {
  const Eigen::Vector3d nominal(0.0017, 0.0042, 0.0054);
  CHECK_FALSE(scale_mimicking_moments(nominal, Eigen::Vector3d(0.0017, 0.0050, 0.0046)).has_value());
}

TEST_CASE("no scale reproduces the symmetric cylinder with moments that break its symmetry",
          "[equivalence]") {
  // The seed paper's GF cylinder (symmetric about z) and a tensor whose transverse
  // moments differ by 6 %.
  const Eigen::Vector3d cylinder(0.01838, 0.01838, 0.02108);
  const Eigen::Vector3d broken(0.01790, 0.01900, 0.02094);
  CHECK_FALSE(scale_mimicking_moments(cylinder, broken).has_value());
  const Flight truth = thrown(broken, Eigen::Vector3d::Zero());
  const double with_scale = misfit(truth, cylinder, Effect::gyro_scale);
  const double with_moments = misfit(truth, cylinder, Effect::inertia_moments);
  INFO("best scale leaves " << with_scale << " rad/s, moments " << with_moments);
  CHECK(with_moments < 1e-4);
  CHECK(with_scale > 100.0 * with_moments);
  CHECK(with_scale > 1e-2);
}
