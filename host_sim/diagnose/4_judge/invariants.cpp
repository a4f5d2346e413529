#include "diagnose/4_judge/invariants.hpp"

#include <cmath>
#include <limits>

namespace aloft::host::diagnose {
namespace {

// Least-squares line through the usable samples, the residual spread about it, and the
// spread the noise alone would cause (propagated to first order).
InvariantBehaviour judge(std::string name, const Flight& flight, const std::vector<double>& value,
                         const std::vector<double>& noise_variance) {
  InvariantBehaviour b;
  b.name = std::move(name);
  b.series = value;
  double n = 0, st = 0, sv = 0, stt = 0, stv = 0, noise = 0;
  for (std::size_t k = 0; k < flight.size(); ++k) {
    if (!flight.usable[k]) continue;
    const double t = flight.time_s[k] - flight.start_s();
    n += 1;
    st += t;
    sv += value[k];
    stt += t * t;
    stv += t * value[k];
    noise += noise_variance[k];
  }
  if (n < 3) return b;
  const double det = n * stt - st * st;
  const double slope = det > 0 ? (n * stv - st * sv) / det : 0.0;
  const double intercept = (sv - slope * st) / n;
  double rss = 0;
  for (std::size_t k = 0; k < flight.size(); ++k) {
    if (!flight.usable[k]) continue;
    const double t = flight.time_s[k] - flight.start_s();
    const double r = value[k] - intercept - slope * t;
    rss += r * r;
  }
  const double mean = sv / n;
  const double duration = flight.end_s() - flight.start_s();
  const double spread_var = rss / (n - 2);
  const double noise_var = noise / n;
  b.mean = mean;
  b.relative_change = mean != 0 ? slope * duration / mean : 0.0;
  b.relative_oscillation = mean != 0 ? std::sqrt(spread_var) / std::abs(mean) : 0.0;
  // Trend: the slope is many standard errors from zero (errors from the larger of the
  // actual and the noise spread) and changes the invariant by more than 0.5 %.
  const double slope_se = det > 0 ? std::sqrt(std::max(spread_var, noise_var) * n / det) : 1e300;
  const bool trend = std::abs(slope) > 5.0 * slope_se && std::abs(b.relative_change) > 0.005;
  // Oscillation: the spread about the line is clearly more than noise, and > 0.2 %.
  const bool oscillation =
      spread_var > noise_var * (1.0 + 6.0 * std::sqrt(2.0 / n)) && b.relative_oscillation > 0.002;
  b.behaviour =
      trend ? (oscillation ? "trend_and_oscillation" : "trend") : (oscillation ? "oscillation" : "constant");
  return b;
}

}  // namespace

Invariants measured_invariants(const Flight& flight, const NominalInertia& nominal, const NoiseFloor& noise) {
  const std::size_t n = flight.size();
  std::vector<double> energy(n, std::numeric_limits<double>::quiet_NaN());
  std::vector<double> momentum = energy;
  std::vector<double> energy_noise(n, 0.0), momentum_noise(n, 0.0);
  const Eigen::Matrix3d to_body = flight.sensor_to_body.toRotationMatrix();
  // Noise of the readings in body axes (diagonal, from the per-axis floor).
  const Eigen::Matrix3d reading_cov = noise.sigma.cwiseAbs2().asDiagonal();
  const Eigen::Matrix3d body_cov = to_body * reading_cov * to_body.transpose();
  const Eigen::Matrix3d& inertia = nominal.tensor;
  for (std::size_t k = 0; k < n; ++k) {
    if (!flight.usable[k]) continue;
    const Eigen::Vector3d w = to_body * flight.omega[k];
    const Eigen::Vector3d l = inertia * w;
    energy[k] = 0.5 * w.dot(l);
    momentum[k] = l.norm();
    // dE/dw = Iw, d|L|/dw = I L/|L|.
    energy_noise[k] = l.dot(body_cov * l);
    if (momentum[k] > 0) {
      const Eigen::Vector3d g = inertia * l / momentum[k];
      momentum_noise[k] = g.dot(body_cov * g);
    }
  }
  Invariants out;
  out.energy = judge("kinetic_energy", flight, energy, energy_noise);
  out.momentum = judge("angular_momentum", flight, momentum, momentum_noise);
  return out;
}

}  // namespace aloft::host::diagnose
