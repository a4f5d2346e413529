#include "readers/rate_units_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/commands.hpp"

namespace aloft::host {
namespace {

// Samples per span over which the change of ω is compared with Euler's equations: long
// enough that the change stands above the gyro's noise, short enough that the
// trapezoidal integral of the prediction is exact to well under a percent.
constexpr std::size_t kSpan = 10;
// c is trusted where it explains at least this share of the change of ω.
constexpr double kExplained = 0.5;
// A c within this factor of a unit's is taken for that unit. On every IMU trial of
// ../shared/data (SI units, some tensors wrong by up to 4 times) c lies within 0.58-1.21
// wherever it explains half the change of ω: 33 times off the nearest unit's, 1/57.3.
constexpr double kNearUnit = 1.5;

Eigen::Vector3d euler_rate(const Eigen::Matrix3d& inertia, const Eigen::Matrix3d& inverse,
                           const Eigen::Vector3d& w) {
  return inverse * (inertia * w).cross(w);
}

struct Sums {
  double change_dot_prediction = 0.0, prediction_squared = 0.0, change_squared = 0.0;
  std::size_t spans = 0;
};

void add_flight(const RateSeries& f, const Eigen::Matrix3d& inertia, const Eigen::Matrix3d& inverse,
                Sums& s) {
  const Eigen::Matrix3d to_body = f.sensor_to_body.toRotationMatrix();
  for (std::size_t i = 0; i + kSpan < f.size(); i += kSpan) {
    bool usable = true;
    Eigen::Vector3d prediction = Eigen::Vector3d::Zero();
    for (std::size_t k = i; k < i + kSpan; ++k) {
      usable = usable && f.usable[k] && f.usable[k + 1];
      const Eigen::Vector3d a = euler_rate(inertia, inverse, to_body * f.omega[k]);
      const Eigen::Vector3d b = euler_rate(inertia, inverse, to_body * f.omega[k + 1]);
      prediction += 0.5 * (a + b) * (f.time_s[k + 1] - f.time_s[k]);
    }
    if (!usable) continue;
    const Eigen::Vector3d change = to_body * (f.omega[i + kSpan] - f.omega[i]);
    s.change_dot_prediction += change.dot(prediction);
    s.prediction_squared += prediction.squaredNorm();
    s.change_squared += change.squaredNorm();
    ++s.spans;
  }
}

struct Unit {
  double c;           // the scale a log in this unit shows
  const char* cause;  // what is wrong
  const char* fix;    // the option that converts it
};

// The units a log is likely in, by the scale c they show (SI: 1).
constexpr Unit kUnits[] = {
    {M_PI / 180.0, "the gyro reads in °/s (a uniform gyro scale of 57.3)", "--gyro-units deg/s"},
    {1e-3, "the times are in ms (a clock running 1000 times too fast)", "--time-units ms"},
    {1e-6, "the times are in µs (a clock running 10^6 times too fast)", "--time-units us"},
    {M_PI / 180.0 * 1e-3, "the gyro reads in °/s and the times are in ms",
     "--gyro-units deg/s --time-units ms"},
    {180.0 / M_PI, "the gyro already reads rad/s but was read as °/s", "no --gyro-units deg/s"},
    {1e3, "the times are already in s but were read as ms", "no --time-units ms"},
};

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace

EulerScale euler_scale(const std::vector<RateSeries>& flights, const Body& body) {
  const Eigen::Matrix3d inertia = body.inertia.tensor(), inverse = body.inertia.inverse();
  Sums s;
  for (const RateSeries& f : flights) add_flight(f, inertia, inverse, s);
  EulerScale out;
  out.spans = s.spans;
  if (!(s.prediction_squared > 0.0) || !(s.change_squared > 0.0)) return out;
  out.c = s.change_dot_prediction / s.prediction_squared;
  const double residual = s.change_squared - out.c * s.change_dot_prediction;
  out.explained = 1.0 - residual / s.change_squared;
  return out;
}

void check_rate_units(const std::vector<RateSeries>& flights, const Body& body, const std::string& source) {
  const EulerScale scale = euler_scale(flights, body);
  if (scale.explained < kExplained || !(scale.c > 0.0)) return;
  const std::string seen = "ω changes " + format("%.3g", scale.c) +
                           " times as fast as Euler's equations say for these rates and the body's "
                           "tensor (1 in s and rad/s; " +
                           format("%.0f", 100.0 * scale.explained) + " % of the change explained)";
  for (const Unit& u : kUnits) {
    if (std::abs(std::log(scale.c / u.c)) < std::log(kNearUnit)) {
      throw Error(source + ": " + u.cause + ": " + seen + "; give " + u.fix);
    }
  }
  // Any other c is left to the diagnosis: a wrong tensor moves c too (by up to 1.7 times
  // on ../shared/data's wrong-moment sessions), and the diagnosis names a wrong tensor.
}

}  // namespace aloft::host
