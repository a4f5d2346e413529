#include "ceres/effect_fit_problem.hpp"

#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/3_fit/held_out.hpp"
#include "diagnose/3_fit/initial_state_fit.hpp"
#include "diagnose/4_judge/noise_floor.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

// The weighted residuals of `readings`, zero on samples the fit does not use (their
// count stays fixed, as ArrowProblem asks).
void weighted_residuals(const FlightData& d, const std::vector<Vec3>& readings, Eigen::VectorXd& r) {
  const Flight& flight = *d.flight;
  r.setZero(static_cast<Eigen::Index>(3 * flight.size()));
  for (std::size_t k = 0; k < flight.size(); ++k) {
    if (d.mask[k] && flight.usable[k]) {
      r.segment<3>(static_cast<Eigen::Index>(3 * k)) =
          (readings[k] - flight.omega[k]).cwiseProduct(d.inverse_sigma);
    }
  }
}

// fit_effect's starting rates for a single effect from the nominal fit: the nominal
// prediction's rate at the effect's reference sample, refined with the rigid body for an
// effect whose theta is never the nominal model.
std::vector<Eigen::VectorXd> starting_rates(const EffectFitProblem& fit) {
  const bool rigid = !describe(fit.model.effect).neutral_at_zero;
  std::vector<Eigen::VectorXd> rates;
  std::vector<Vec3> readings;
  for (std::size_t i = 0; i < fit.flights.size(); ++i) {
    predict(fit.nominal_fit, fit.model.nominal, i, fit.flights[i], readings);
    Vec3 rate = body_rate_of_reading(fit.flights[i], readings[fit.refs[i]]);
    if (rigid) {
      const EffectModel nominal_model(Effect::none, fit.model.nominal);
      rate = fit_initial_state(nominal_model, fit.data[i], fit.refs[i], Eigen::VectorXd(), &rate).omega_ref;
    }
    rates.emplace_back(rate);
  }
  return rates;
}

}  // namespace

std::unique_ptr<EffectFitProblem> effect_fit_problem(Effect effect, std::vector<Flight> flights,
                                                     const NominalInertia& nominal) {
  auto fit = std::make_unique<EffectFitProblem>();
  fit->flights = std::move(flights);
  fit->model = EffectModel(effect, nominal);
  for (const Flight& flight : fit->flights) {
    const Vec3 inverse_sigma = estimate_noise_floor(flight).weighting_sigma().cwiseInverse();
    fit->data.push_back(FlightData{&flight, all_samples(flight.size()), inverse_sigma});
    fit->refs.push_back(reference_index(effect, flight));
  }
  fit->nominal_fit = fit_effect(Effect::none, nominal, fit->data, nullptr);
  fit->rates_start = starting_rates(*fit);
  const StartGrid* grid = describe(effect).start_grid;
  fit->theta_start =
      grid != nullptr ? grid->joining() : Eigen::VectorXd::Zero(effect_parameter_count(effect));
  ArrowProblem& problem = fit->problem;
  problem.shared_count = static_cast<int>(fit->theta_start.size());
  problem.local_count = 3;
  problem.block_count = static_cast<int>(fit->flights.size());
  const EffectFitProblem* owner = fit.get();
  problem.residuals = [owner](int block, const Eigen::VectorXd& theta, const Eigen::VectorXd& rate,
                              Eigen::VectorXd& r) {
    const std::size_t b = static_cast<std::size_t>(block);
    std::vector<Vec3> readings;
    predict_readings(owner->model, owner->flights[b], owner->refs[b], Vec3(rate), theta, readings);
    weighted_residuals(owner->data[b], readings, r);
    owner->simulations.fetch_add(1, std::memory_order_relaxed);
  };
  return fit;
}

}  // namespace aloft::host::diagnose
