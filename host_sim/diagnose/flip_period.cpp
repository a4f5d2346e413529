#include "diagnose/flip_period.hpp"

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

std::optional<double> predicted_period(const Flight& flight, const NominalInertia& nominal,
                                       const EffectModel& model, const Eigen::VectorXd& theta) {
  const Eigen::Vector3d start = body_rate_for_reading(model, flight, theta, flight.omega.front());
  std::vector<Eigen::Vector3d> readings;
  predict_readings(model, flight, 0, start, theta, readings);
  return point_method_period(flight.time_s, intermediate_component(flight, nominal, readings));
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
                                      const EffectModel* diagnosed, const Eigen::VectorXd& theta) {
  if (flight.size() < 5) return std::nullopt;
  const auto measured = point_method_period(flight.time_s, intermediate_component(flight, nominal, flight.omega));
  const EffectModel plain{Effect::none, nominal, 0.0};
  const auto nominal_period = predicted_period(flight, nominal, plain, Eigen::VectorXd());
  if (!measured || !nominal_period) return std::nullopt;
  FlipPeriod out;
  out.measured_s = *measured;
  out.nominal_s = *nominal_period;
  if (diagnosed != nullptr) out.diagnosed_s = predicted_period(flight, nominal, *diagnosed, theta);
  return out;
}

}  // namespace aloft::host::diagnose
