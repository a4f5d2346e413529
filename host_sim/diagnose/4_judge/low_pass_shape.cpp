#include "diagnose/4_judge/low_pass_shape.hpp"

#include <algorithm>
#include <cmath>

namespace aloft::host::diagnose {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

LowPassShape::LowPassShape(Kind kind, double cutoff_hz, double sample_hz)
    : kind_(kind), cutoff_hz_(cutoff_hz), sample_hz_(sample_hz) {
  if (cutoff_hz <= 0.0) return;
  if (kind == Kind::butterworth) {
    cutoff_abscissa_ = std::tan(kPi * cutoff_hz / sample_hz);
  } else {
    const double rc = 1.0 / (2.0 * kPi * cutoff_hz), dt = 1.0 / sample_hz;
    k_ = dt / (rc + dt);
  }
}

double LowPassShape::abscissa(Kind kind, double f_hz, double sample_hz) {
  const double f = std::min(f_hz, 0.4999 * sample_hz);
  return kind == Kind::butterworth ? std::tan(kPi * f / sample_hz) : std::cos(2.0 * kPi * f / sample_hz);
}

double LowPassShape::gain_at(double abscissa) const {
  if (cutoff_hz_ <= 0.0) return 1.0;
  if (kind_ == Kind::butterworth) {
    const double r = abscissa / cutoff_abscissa_;
    return 1.0 / (1.0 + r * r * r * r);
  }
  const double a = 1.0 - k_;
  const double stage = k_ * k_ / (1.0 + a * a - 2.0 * a * abscissa);
  return kind_ == Kind::two_first_order ? stage * stage : stage;
}

double LowPassShape::bend_s2() const {
  if (cutoff_hz_ <= 0.0 || kind_ == Kind::butterworth) return 0.0;
  const double dt = 1.0 / sample_hz_;
  const double stage_variance = dt * dt * (1.0 - k_) / (k_ * k_);  // RC (RC + dt)
  return 0.5 * stage_variance * (kind_ == Kind::two_first_order ? 2.0 : 1.0);
}

const char* LowPassShape::name() const {
  switch (kind_) {
    case Kind::butterworth: return "butterworth";
    case Kind::first_order: return "pt1";
    case Kind::two_first_order: return "pt2";
  }
  return "butterworth";
}

}  // namespace aloft::host::diagnose
