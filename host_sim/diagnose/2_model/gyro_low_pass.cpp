#include "diagnose/2_model/gyro_low_pass.hpp"

#include <cmath>

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;
constexpr double kPi = 3.14159265358979323846;

// y += k (x - y), k = dt / (RC + dt): a flight controller's PT1 as the generator and
// low_pass_shape.hpp write it.
void first_order(double cutoff_hz, double sample_hz, std::vector<Vec3>& readings) {
  const double rc = 1.0 / (2.0 * kPi * cutoff_hz), dt = 1.0 / sample_hz, k = dt / (rc + dt);
  Vec3 y = readings.front();
  for (Vec3& x : readings) {
    y += k * (x - y);
    x = y;
  }
}

// A second-order Butterworth by the bilinear transform (prewarped to the cutoff).
void butterworth(double cutoff_hz, double sample_hz, std::vector<Vec3>& readings) {
  const double c = std::tan(kPi * cutoff_hz / sample_hz);
  const double norm = 1.0 / (1.0 + std::sqrt(2.0) * c + c * c);
  const double b0 = c * c * norm, b1 = 2.0 * b0, b2 = b0;
  const double a1 = 2.0 * (c * c - 1.0) * norm, a2 = (1.0 - std::sqrt(2.0) * c + c * c) * norm;
  Vec3 x1 = readings.front(), x2 = x1, y1 = x1, y2 = x1;
  for (Vec3& x : readings) {
    const Vec3 y = b0 * x + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
    x2 = x1;
    x1 = x;
    y2 = y1;
    y1 = y;
    x = y;
  }
}

}  // namespace

void pass_through_low_pass(const Flight& flight, std::vector<Vec3>& readings) {
  if (!behind_low_pass(flight) || readings.empty()) return;
  const GyroLowPass& f = flight.low_pass;
  if (f.order == 1) {
    first_order(f.cutoff_hz, f.sample_hz, readings);
  } else {
    butterworth(f.cutoff_hz, f.sample_hz, readings);
  }
}

}  // namespace aloft::host::diagnose
