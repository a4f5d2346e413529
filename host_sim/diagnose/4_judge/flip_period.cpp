#include "diagnose/4_judge/flip_period.hpp"

#include <algorithm>
#include <cmath>

namespace aloft::host::diagnose {
namespace {

std::vector<double> intermediate_component(const Flight& flight, const NominalInertia& nominal,
                                           const std::vector<Eigen::Vector3d>& readings) {
  const Eigen::Vector3d axis = nominal.principal_axes.toRotationMatrix().col(1);
  std::vector<double> out;
  for (const auto& r : readings) out.push_back(axis.dot(flight.sensor_to_body * r));
  return out;
}

std::optional<double> period_from(const Flight& flight, const NominalInertia& nominal,
                                  const EffectModel& model, const Eigen::VectorXd& theta,
                                  const FlightState& start) {
  std::vector<Eigen::Vector3d> readings;
  predict_readings(model, flight, start.ref, start.omega_ref, theta, readings);
  return point_method_period(flight.time_s, intermediate_component(flight, nominal, readings));
}

// The first reading taken as the body rate (through the model's sensor, if it has one).
FlightState first_sample(const EffectModel& model, const Flight& flight, const Eigen::VectorXd& theta) {
  FlightState start;
  start.omega_ref = body_rate_for_reading(model, flight, theta, flight.omega.front());
  return start;
}

}  // namespace

std::optional<double> point_method_period(const std::vector<double>& t, const std::vector<double>& v) {
  std::vector<double> events;
  const std::size_t n = v.size();
  for (std::size_t k = 1; k < n; ++k) {
    if ((v[k - 1] < 0) != (v[k] < 0) && v[k] != v[k - 1]) {
      events.push_back(t[k - 1] - v[k - 1] * (t[k] - t[k - 1]) / (v[k] - v[k - 1]));
    }
  }
  for (std::size_t k = 2; k + 2 < n; ++k) {
    const auto lo = v.begin() + static_cast<std::ptrdiff_t>(k - 2);
    const auto hi = v.begin() + static_cast<std::ptrdiff_t>(k + 3);
    if (v[k] == *std::max_element(lo, hi) || v[k] == *std::min_element(lo, hi)) events.push_back(t[k]);
  }
  if (events.size() < 2) return std::nullopt;
  std::sort(events.begin(), events.end());
  double sum = 0.0;
  for (std::size_t i = 1; i < events.size(); ++i) sum += events[i] - events[i - 1];
  return 4.0 * sum / static_cast<double>(events.size() - 1);
}

std::optional<FlipPeriod> flip_period(const Flight& flight, const NominalInertia& nominal,
                                      const EffectModel* diagnosed, const Eigen::VectorXd& theta,
                                      const FlightState* nominal_start, const FlightState* diagnosed_start) {
  if (flight.size() < 5) return std::nullopt;
  const auto measured =
      point_method_period(flight.time_s, intermediate_component(flight, nominal, flight.omega));
  const EffectModel plain{Effect::none, nominal, 0.0};
  const Eigen::VectorXd none;
  const auto nominal_period = period_from(flight, nominal, plain, none, first_sample(plain, flight, none));
  if (!measured || !nominal_period) return std::nullopt;
  FlipPeriod out;
  out.measured_s = *measured;
  out.nominal_s = *nominal_period;
  if (nominal_start != nullptr)
    out.nominal_fitted_s = period_from(flight, nominal, plain, none, *nominal_start);
  if (diagnosed == nullptr) return out;
  out.diagnosed_s = period_from(flight, nominal, *diagnosed, theta, first_sample(*diagnosed, flight, theta));
  if (diagnosed_start != nullptr)
    out.diagnosed_fitted_s = period_from(flight, nominal, *diagnosed, theta, *diagnosed_start);
  return out;
}

}  // namespace aloft::host::diagnose
