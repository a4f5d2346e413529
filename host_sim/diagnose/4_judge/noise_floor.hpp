// The noise floor of a flight's readings. Where the log has rest periods around the
// flight (Flight::rest_noise, rest_periods.hpp), their spread; otherwise estimated from
// the flight alone: the spread of high-order differences of consecutive samples, where a
// smooth motion contributes almost nothing and white noise a known multiple of its
// variance. Either way never below the rounding noise of the data's resolution.
//
// A gyro's low-pass (a fast gyro behind a 20-400 Hz filter, a Butterworth or a flight
// controller's first-order PT1 or PT2: low_pass_shape.hpp) makes its noise correlated:
// the differences of neighbouring samples see only the top of its band and understate it
// many times over, and neighbouring samples are not independent. There the spectrum of
// the readings (noise_spectrum.hpp) gives both: the noise's variance (its band's power,
// flat below the band where the motion hides it) and how many samples make one
// independent one (`correlation`: the spectrum's level at low frequencies over the level
// of a white noise of that variance). Fits weigh the readings by `weighting_sigma`, so that
// a correlated noise's chi-square counts its independent samples, not its readings.
#pragma once

#include <Eigen/Core>

#include <cmath>

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
  // spread of high-order differences), "spectrum" (a gyro's noise behind a low-pass,
  // from the readings' spectrum) or "resolution" (the floor is held at
  // resolution/sqrt(12), the rounding noise, because the estimate of smooth, filtered or
  // quantised data fell below it).
  const char* method = "differences";
  // Readings per independent sample (>= 1): 1 for white noise; for noise behind a
  // low-pass (method "spectrum"), about the rate over 2.2 times the cutoff behind a
  // Butterworth, over pi times the cutoff behind a first-order PT1, twice that behind a PT2.
  double correlation = 1.0;
  double low_pass_hz = 0.0;  // method "spectrum": the gyro's low-pass as fitted (0: none)
  // Its order (low_pass_shape.hpp): 2, a Butterworth or a PT2; 1, a first-order PT1; 0, none;
  // and its shape: "butterworth", "pt1", "pt2" or "none".
  int low_pass_order = 0;
  const char* low_pass_shape = "none";
  // Its bend of the motion (LowPassShape::bend_s2, s^2), the diagnosis's
  // Flight::gyro_filter_bend_s2; 0 where none was fitted or its knee is too near the motion.
  double low_pass_bend_s2 = 0.0;
  // What fits weigh the readings by: sigma * sqrt(correlation), the white noise whose
  // chi-square over the readings is that of the correlated noise over its independent
  // samples (the same low-frequency density).
  Eigen::Vector3d weighting_sigma() const { return sigma * std::sqrt(correlation); }
};

// Differences spanning a time gap or an unusable sample are skipped; the median of the
// squared differences (not the mean) keeps an impulse or a glitch from inflating it.
// A floor of 1e-6 rad/s stops noise-free (synthetic) data from weighting infinitely.
// The floor is never below the rounding noise of the data's resolution.
NoiseFloor estimate_noise_floor(const Flight& flight);

// The smallest step between distinct readings of each axis, median over the axes.
double reading_resolution(const Flight& flight);

}  // namespace aloft::host::diagnose
