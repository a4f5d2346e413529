#include "diagnose/3_fit/effect_fit_result.hpp"

namespace aloft::host::diagnose {

EffectModel model_of(const EffectFit& fit, const NominalInertia& nominal, std::size_t index) {
  EffectModel model{fit.effect, nominal, 0.0, fit.base};
  if (index < fit.flights.size()) model.impulse_time_s = fit.flights[index].impulse_time_s;
  return model;
}

void predict(const EffectFit& fit, const NominalInertia& nominal, std::size_t index, const Flight& flight,
             std::vector<Eigen::Vector3d>& readings) {
  const FlightState& state = fit.flights[index];
  predict_readings(model_of(fit, nominal, index), flight, state.ref, state.omega_ref, fit.theta, readings);
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
