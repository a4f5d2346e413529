// The power spectrum of a flight's readings, per axis, for the noise floor of a fast or
// filtered gyro (noise_floor.hpp). A tumbling body's rates are smooth, periodic functions
// whose spectrum falls off faster than any power of the frequency past a few harmonics of
// the tumble (a few Hz); a gyro's noise is white, or white behind the sensor's low-pass
// (flat to its cutoff, then falling). So the spectrum above the motion's band is the
// noise's, and its level there is the noise's level at low frequencies as well.
//
// Welch's estimate: segments of a power-of-two length overlapping by half, each with its
// least-squares quadratic taken off and a 4-term Blackman-Harris window (side lobes 92 dB
// down, so the motion's 10 rad/s leaks less than a 0.001 rad/s noise puts in a bin); each
// bin the median over the segments (not the mean), so that an impulse's step, whose
// spectrum falls only as 1/f², in one or two segments does not pass for noise; divided by
// that median's expected value for a noise of unit power, so the density is unbiased.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace aloft::host::diagnose {

struct NoiseSpectrum {
  double bin_hz = 0.0;     // spacing of the bins
  double sample_hz = 0.0;  // the readings' rate
  // One-sided power spectral density per bin (bin j at j * bin_hz, j = 0 .. L/2), per
  // axis, units²/Hz: the sum of a band's bins times bin_hz is the variance in that band.
  std::vector<Eigen::Vector3d> density;
  int segments = 0;
};

// The spectrum of readings sampled evenly at `sample_hz`; empty (no bins) when there are
// fewer than kShortestSpectrum samples.
NoiseSpectrum welch_spectrum(const std::vector<Eigen::Vector3d>& readings, double sample_hz);

// Segments shorter than this resolve too few bins above a tumble's harmonics; data
// shorter than kShortestSpectrum give fewer than four half-overlapping segments (a 100 Hz
// flight of 0.8 s has 80 samples: four segments of 32).
constexpr int kShortestSegment = 32;
constexpr int kShortestSpectrum = 5 * kShortestSegment / 2;

}  // namespace aloft::host::diagnose
