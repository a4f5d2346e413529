#include "diagnose/2_model/momentum_from_readings.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "diagnose/2_model/flight_model.hpp"

namespace aloft::host::diagnose {
namespace {

// dw/dt from readings kDerivativeHalfSpan_s either side (at least one sample): at 1 kHz
// two samples, so that a 0.01 rad/s noise adds about 3.5 rad/s² to a sample's derivative
// where the tumble's own w × I w / I is of order |w|² (100 rad/s² at 10 rad/s); at 100 Hz
// the neighbours themselves.
constexpr double kDerivativeHalfSpan_s = 0.002;
// A difference across a gap of more than this many times its expected span is left out.
constexpr double kLongestSpan = 1.5;
// The ridge, relative to the normal matrix's trace: far below any informed direction's
// share (a tumble informs all three), enough to solve a single-axis spin.
constexpr double kRidge = 1e-9;

// The normal equations of one flight's balance, added to (a, b).
void add_flight(const Flight& flight, const Eigen::Matrix3d& inertia, Eigen::Matrix3d& a,
                Eigen::Vector3d& b) {
  const std::size_t n = flight.size();
  if (n < 3) return;
  const double step_s = (flight.time_s.back() - flight.time_s.front()) / static_cast<double>(n - 1);
  if (!(step_s > 0.0)) return;
  const std::size_t d =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(kDerivativeHalfSpan_s / step_s)));
  for (std::size_t k = d; k + d < n; ++k) {
    if (!flight.usable[k - d] || !flight.usable[k] || !flight.usable[k + d]) continue;
    const double span_s = flight.time_s[k + d] - flight.time_s[k - d];
    if (!(span_s > 0.0) || span_s > kLongestSpan * 2.0 * static_cast<double>(d) * step_s) continue;
    const Eigen::Vector3d w = body_rate_of_reading(flight, flight.omega[k]);
    const Eigen::Vector3d dw = (body_rate_of_reading(flight, flight.omega[k + d]) -
                                body_rate_of_reading(flight, flight.omega[k - d])) /
                               span_s;
    const Eigen::Vector3d r = -(inertia * dw + w.cross(inertia * w));
    a += w.squaredNorm() * Eigen::Matrix3d::Identity() - w * w.transpose();
    b += r.cross(w);
  }
}

}  // namespace

Eigen::VectorXd momentum_theta_from_readings(const std::vector<const Flight*>& flights,
                                             const NominalInertia& nominal) {
  Eigen::Matrix3d a = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (const Flight* flight : flights) add_flight(*flight, nominal.tensor, a, b);
  if (!(a.trace() > 0.0)) return Eigen::VectorXd::Zero(3);
  a += kRidge * a.trace() * Eigen::Matrix3d::Identity();
  const Eigen::Vector3d h = a.ldlt().solve(b);
  return Eigen::VectorXd(nominal.tensor.ldlt().solve(h));
}

}  // namespace aloft::host::diagnose
