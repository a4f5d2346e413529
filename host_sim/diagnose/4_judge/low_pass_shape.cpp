#include "diagnose/4_judge/low_pass_shape.hpp"

#include <algorithm>
#include <cmath>

namespace aloft::host::diagnose {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

LowPassShape::LowPassShape(int order, double cutoff_hz, double sample_hz)
    : order_(order), cutoff_hz_(cutoff_hz), sample_hz_(sample_hz) {
  if (cutoff_hz <= 0.0) return;
  if (order == kFirstOrder) {
    const double rc = 1.0 / (2.0 * kPi * cutoff_hz), dt = 1.0 / sample_hz;
    k_ = dt / (rc + dt);
  } else {
    cutoff_abscissa_ = std::tan(kPi * cutoff_hz / sample_hz);
  }
}

double LowPassShape::abscissa(int order, double f_hz, double sample_hz) {
  const double f = std::min(f_hz, 0.4999 * sample_hz);
  return order == kFirstOrder ? std::cos(2.0 * kPi * f / sample_hz) : std::tan(kPi * f / sample_hz);
}

double LowPassShape::gain_at(double abscissa) const {
  if (cutoff_hz_ <= 0.0) return 1.0;
  if (order_ == kFirstOrder) {
    const double a = 1.0 - k_;
    return k_ * k_ / (1.0 + a * a - 2.0 * a * abscissa);
  }
  const double r = abscissa / cutoff_abscissa_;
  return 1.0 / (1.0 + r * r * r * r);
}

}  // namespace aloft::host::diagnose
