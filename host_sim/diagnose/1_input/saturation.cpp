#include "diagnose/1_input/saturation.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace aloft::host::diagnose {
namespace {

// How far above a flat run (towards its sign) the motion either side of it, extrapolated,
// reaches: a parabola in time fitted to the run's length of samples before and after it
// (at least kSideSamples each), its largest value over the run less the run's level, and
// the fit's residual spread. A saturated gyro's true rate rises past the flat top, so the
// parabola through its sides does too (a sine clipped at 95 % of its peak: by 5 % of it);
// a smooth peak read through a fine quantisation (a flight controller's 1/16.4 deg/s at
// 8 kHz stays within one step for tens of readings) sits where the parabola peaks.
constexpr std::size_t kSideSamples = 4;
struct Overshoot {
  double above = 0.0;   // rad/s, towards the run's sign
  double spread = 0.0;  // the parabola's residual RMS on the sides
  bool known = false;   // enough samples on both sides
};
Overshoot overshoot(const Flight& f, int axis, std::size_t first, std::size_t end) {
  const std::size_t side = std::max(kSideSamples, end - first);
  Overshoot out;
  if (first < side || end + side > f.size()) return out;
  const double sign = f.omega[first](axis) < 0.0 ? -1.0 : 1.0, t0 = f.time_s[first];
  const double span = std::max(f.time_s[end - 1] - t0, 1e-9);
  Eigen::MatrixXd a(2 * side, 3);
  Eigen::VectorXd b(2 * side);
  for (std::size_t i = 0; i < 2 * side; ++i) {
    const std::size_t k = i < side ? first - side + i : end + (i - side);
    const double u = (f.time_s[k] - t0) / span;
    a.row(static_cast<Eigen::Index>(i)) << 1.0, u, u * u;
    b(static_cast<Eigen::Index>(i)) = sign * f.omega[k](axis);
  }
  const Eigen::Vector3d c = a.colPivHouseholderQr().solve(b);
  double highest = std::max(c(0), c(0) + c(1) + c(2));
  if (c(2) < 0.0) {
    const double u = -c(1) / (2.0 * c(2));
    if (u > 0.0 && u < 1.0) highest = std::max(highest, c(0) + c(1) * u + c(2) * u * u);
  }
  out.above = highest - sign * f.omega[first](axis);
  out.spread = std::sqrt((a * c - b).squaredNorm() / static_cast<double>(2 * side));
  out.known = true;
  return out;
}

// A flat run is a saturated top where the motion either side rises past it by more than
// kPastTop times what the parabola misses by (noise, and a quantisation's staircase) and
// kPastTop steps of the readings (the smallest between neighbours either side; a smooth
// peak's parabola through a staircase lands within a step of its top); where the run
// reaches an end of the flight, nothing can tell, and it counts as one.
constexpr double kPastTop = 4.0;
bool clipped(const Flight& f, int axis, std::size_t first, std::size_t end) {
  const Overshoot o = overshoot(f, axis, first, end);
  if (!o.known) return true;
  const std::size_t side = std::max(kSideSamples, end - first);
  double step = 0.0;
  for (std::size_t k = first - side + 1; k < end + side; ++k) {
    const double d = std::abs(f.omega[k](axis) - f.omega[k - 1](axis));
    if (d > 0.0 && (step == 0.0 || d < step)) step = d;
  }
  return o.above > kPastTop * (o.spread + step);
}

}  // namespace

Saturation mark_saturated_samples(Flight& flight) {
  Saturation out;
  const std::size_t n = flight.size();
  if (flight.usable.size() != n) flight.usable.assign(n, 1);
  std::vector<char> flat(n, 0);
  for (int a = 0; a < 3; ++a) {
    double peak = 0.0;
    for (const auto& w : flight.omega) peak = std::max(peak, std::abs(w(a)));
    if (peak <= 0.0) continue;
    std::size_t k = 0;
    while (k < n) {
      std::size_t end = k + 1;
      while (end < n && flight.omega[end](a) == flight.omega[k](a)) ++end;
      const double level = std::abs(flight.omega[k](a));
      if (end - k >= 3 && level >= 0.9 * peak && clipped(flight, a, k, end)) {
        for (std::size_t j = k; j < end; ++j) flat[j] = 1;
        out.level_rad_s = std::max(out.level_rad_s, level);
      }
      k = end;
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (flat[k] && flight.usable[k]) {
      flight.usable[k] = 0;
      ++out.samples;
    }
  }
  return out;
}

}  // namespace aloft::host::diagnose
