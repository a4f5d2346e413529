#include "diagnose/3_fit/effect_fit_result.hpp"

namespace aloft::host::diagnose {

EffectModel model_of(const EffectFit& fit, const NominalInertia& nominal, std::size_t index) {
  EffectModel model{fit.effect, nominal, 0.0, fit.base};
  if (index < fit.flights.size()) model.impulse_time_s = fit.flights[index].impulse_time_s;
  return model;
}

const Eigen::VectorXd& flight_theta(const EffectFit& fit, std::size_t index) {
  if (index < fit.flights.size() && fit.flights[index].own.size() > 0) return fit.flights[index].theta;
  return fit.theta;
}

Eigen::VectorXd local_of(const EffectFit& fit, std::size_t index) {
  const FlightState& state = fit.flights[index];
  Eigen::VectorXd local(3 + state.own.size());
  local << state.omega_ref, state.own;
  return local;
}

void predict(const EffectFit& fit, const NominalInertia& nominal, std::size_t index, const Flight& flight,
             std::vector<Eigen::Vector3d>& readings) {
  const FlightState& state = fit.flights[index];
  predict_readings(model_of(fit, nominal, index), flight, state.ref, state.omega_ref,
                   flight_theta(fit, index), readings);
}

double weighted_squares(const FlightData& data, const std::vector<Eigen::Vector3d>& readings,
                        int* residual_count) {
  double sum = 0.0;
  int count = 0;
  const Flight& flight = *data.flight;
  for (std::size_t k = 0; k < flight.size(); ++k) {
    if (!data.compared(k)) continue;
    sum += (readings[k] - flight.omega[k]).cwiseProduct(data.inverse_sigma).squaredNorm();
    count += 3;
  }
  if (residual_count != nullptr) *residual_count = count;
  return sum;
}

}  // namespace aloft::host::diagnose
