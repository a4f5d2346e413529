// The noise floor of a flight's readings. Where the log has rest periods around the
// flight (Flight::rest_noise, rest_periods.hpp), their spread; otherwise estimated from
// the flight alone: the spread of high-order differences of consecutive samples, where a
// smooth motion contributes almost nothing and white noise a known multiple of its
// variance. Either way never below the rounding noise of the data's resolution.
#pragma once

#include <Eigen/Core>

#include "diagnose/1_input/flight.hpp"

namespace aloft::host::diagnose {

struct NoiseFloor {
  Eigen::Vector3d sigma = Eigen::Vector3d::Zero();  // per axis, units of the readings
  int difference_order = 0;                         // the order the estimate came from
  bool reliable = false;                            // enough clean differences to tell
  // The data's resolution: the smallest step between distinct readings of an axis (the
  // median over axes): a quantised gyro's step, or the last digit a log was written with.
  double resolution = 0.0;
  // "rest" (the spread of the readings where the sensor lay still), "differences" (the
  // spread of high-order differences) or "resolution" (the floor is held at
  // resolution/sqrt(12), the rounding noise, because the estimate of smooth, filtered or
  // quantised data fell below it).
  const char* method = "differences";
};

// Differences spanning a time gap or an unusable sample are skipped; the median of the
// squared differences (not the mean) keeps an impulse or a glitch from inflating it.
// A floor of 1e-6 rad/s stops noise-free (synthetic) data from weighting infinitely.
// The floor is never below the rounding noise of the data's resolution.
NoiseFloor estimate_noise_floor(const Flight& flight);

// The smallest step between distinct readings of each axis, median over the axes.
double reading_resolution(const Flight& flight);

}  // namespace aloft::host::diagnose
