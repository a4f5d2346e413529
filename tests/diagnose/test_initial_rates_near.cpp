// diagnose/effect_fit: a left-out flight's fold refit of its initial rate started from the
// rate the pooled fit already has (fit_initial_rates_near) reaches the rate and cost of
// the separatrix-safe refit (fit_initial_rates), and where it ends far above the pooled
// fit's cost the safe refit is made and the lower kept.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

#include "diagnose/2_model/flight_model.hpp"
#include "diagnose/3_fit/effect_fit.hpp"
#include "diagnose/3_fit/held_out.hpp"

using namespace aloft::host::diagnose;

namespace {

constexpr std::size_t kSamples = 400;
constexpr double kSigma = 0.01;  // rad/s, the readings' made-up noise

// A 0.4 s flight at 1 kHz of the nominal body read by a gyro with a bias, plus a fixed
// pattern of noise of about kSigma (deterministic, so the test is too).
Flight biased_flight(const NominalInertia& nominal, const Eigen::VectorXd& bias) {
  Flight flight;
  for (std::size_t k = 0; k < kSamples; ++k) flight.time_s.push_back(0.001 * static_cast<double>(k));
  flight.usable.assign(kSamples, 1);
  flight.omega.assign(kSamples, Eigen::Vector3d::Zero());
  const EffectModel model{Effect::gyro_bias, nominal, 0.0, {}};
  predict_readings(model, flight, reference_index(Effect::gyro_bias, flight), Eigen::Vector3d(3.0, 5.0, -2.0),
                   bias, flight.omega);
  for (std::size_t k = 0; k < kSamples; ++k) {
    const double x = static_cast<double>(k);
    flight.omega[k] +=
        kSigma * Eigen::Vector3d(std::sin(1.7 * x), std::cos(2.3 * x), std::sin(0.9 * x + 1.0));
  }
  return flight;
}

}  // namespace

TEST_CASE(
    "fit_initial_rates_near: the fold's rate from the pooled fit's, or the safe fit's where that misses",
    "[initial_rates_near]") {
  const NominalInertia nominal = NominalInertia::of_tensor(Eigen::Vector3d(0.01, 0.02, 0.03).asDiagonal());
  const Eigen::VectorXd bias = Eigen::Vector3d(0.02, -0.01, 0.015);
  const Flight flight = biased_flight(nominal, bias);
  const Eigen::Vector3d inverse_sigma = Eigen::Vector3d::Constant(1.0 / kSigma);
  const FlightData all{&flight, all_samples(kSamples), inverse_sigma};
  const Folds folds = interleaved_folds(kSamples);
  const EffectFit none = fit_effect(Effect::none, nominal, {all}, nullptr);
  const EffectFit pooled = fit_effect(Effect::gyro_bias, nominal, {all}, &none);
  REQUIRE(pooled.cost / pooled.residual_count < 2.0);  // the bias found: a misfit of about the noise

  for (std::size_t f = 0; f < 2; ++f) {
    const FlightData train{&flight, folds.train[f], inverse_sigma};
    // Close to the pooled bias (as a fit without this flight is): the start from the
    // pooled rate is kept, and it ends where the safe refit does.
    EffectFit near_bias = pooled;
    near_bias.theta += Eigen::Vector3d(0.002, 0.001, -0.001);
    const EffectFit cheap = fit_initial_rates_near(near_bias, nominal, train, pooled, 0, &none);
    const EffectFit safe = fit_initial_rates(near_bias, nominal, {train}, &none);
    CHECK(std::abs(cheap.cost - safe.cost) <= 1e-6 * safe.cost);
    CHECK((cheap.flights[0].omega_ref - safe.flights[0].omega_ref).norm() < 1e-5);
    CHECK(cheap.theta == near_bias.theta);

    // A bias far from the pooled one misfits the fold many times over: the safe refit is
    // made too, and nothing worse than it comes back.
    EffectFit far_bias = pooled;
    far_bias.theta += Eigen::Vector3d(0.3, -0.2, 0.25);
    const EffectFit far_cheap = fit_initial_rates_near(far_bias, nominal, train, pooled, 0, &none);
    const EffectFit far_safe = fit_initial_rates(far_bias, nominal, {train}, &none);
    REQUIRE(far_safe.cost > kNearRateCostRatio * pooled.cost);
    CHECK(far_cheap.cost <= far_safe.cost);
  }
}
