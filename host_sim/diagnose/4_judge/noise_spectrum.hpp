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
// Where the step's segments outlie, the noise floor takes them out altogether
// (without_outlying_segments).
#pragma once

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <vector>

namespace aloft::host::diagnose {

struct NoiseSpectrum {
  double bin_hz = 0.0;     // spacing of the bins
  double sample_hz = 0.0;  // the readings' rate
  // One-sided power spectral density per bin (bin j at j * bin_hz, j = 0 .. L/2), per
  // axis, units²/Hz: the sum of a band's bins times bin_hz is the variance in that band.
  std::vector<Eigen::Vector3d> density;
  int segments = 0;
  // The window's power response, normalised to sum 1: a bin's expected density is the
  // true density averaged over the frequencies near it with these weights, at steps of
  // 1 / kResponseSteps bin from -kResponseBins to +kResponseBins bins
  // (expected_densities). A spectrum that bends within a few bins (a low-pass's knee seen
  // through 8 Hz bins) comes out smoothed: its roll-off's first bins 13-28 % above the
  // true density behind 20 Hz at 8 kHz in 1024-sample segments, which read as a steeper
  // roll-off, a lower cutoff (15.6 Hz fitted for 20 in half of 200 runs of noise alone)
  // and a noise overstated 1.4 times.
  std::vector<double> response;
  // Each segment's power per bin and axis, before the median: [segment][bin].
  std::vector<std::vector<Eigen::Vector3d>> segment_power;
};

// The response's resolution and reach: the 4-term Blackman-Harris window's main lobe
// spans +-4 bins; beyond +-5 its side lobes are 92 dB down.
constexpr int kResponseSteps = 8;
constexpr int kResponseBins = 5;

// The frequencies (Hz) at which a true one-sided density enters the expected densities of
// bins first .. last - 1: kResponseSteps a bin, reaching kResponseBins past each end, as
// |f| (the density is even in f, so the response's reach below 0 Hz folds back).
std::vector<double> response_frequencies(const NoiseSpectrum& s, std::size_t first, std::size_t last);

// The expected densities of those bins from the true density's values at
// response_frequencies (in its order): each bin the response-weighted sum about it.
std::vector<double> densities_seen(const NoiseSpectrum& s, const std::vector<double>& true_density);

// The expected densities of bins first .. last - 1 for a true one-sided density
// `true_density(f_hz)`, evaluated once per response step, not once per bin and step.
template <typename Density>
std::vector<double> expected_densities(const NoiseSpectrum& s, std::size_t first, std::size_t last,
                                       const Density& true_density) {
  std::vector<double> fine = response_frequencies(s, first, last);
  for (double& f : fine) f = true_density(f);
  return densities_seen(s, fine);
}

// The spectrum of readings sampled evenly at `sample_hz`; empty (no bins) when there are
// fewer than kShortestSpectrum samples.
NoiseSpectrum welch_spectrum(const std::vector<Eigen::Vector3d>& readings, double sample_hz);

// The spectrum with the medians taken over the segments whose power over bins first ..
// last - 1 (three axes summed) is at most kOutlyingBandPower times the median segment's:
// an impulse's step, whose power falls only as 1/f^2 against a filtered noise's 1/f^4
// past the knee, lifts the one or two segments it lies in far above that just above the
// motion's band, and even passed over by the median it shifts it a rank or two (25 % at
// 12 segments, most just above the band, a roll-off read too steep). Over a band of a few
// bins on three axes a segment of noise alone has at least 12 degrees of freedom
// (neighbouring bins share the window's main lobe), whose power exceeds 2.9 times its
// median once in 1000. The spectrum as it is when no segment outlies, or fewer than
// kFewestKeptSegments would be left.
constexpr double kOutlyingBandPower = 4.0;
constexpr int kFewestKeptSegments = 3;
NoiseSpectrum without_outlying_segments(const NoiseSpectrum& s, std::size_t first, std::size_t last);

// Segments shorter than this resolve too few bins above a tumble's harmonics; data
// shorter than kShortestSpectrum give fewer than four half-overlapping segments (a 100 Hz
// flight of 0.8 s has 80 samples: four segments of 32).
constexpr int kShortestSegment = 32;
constexpr int kShortestSpectrum = 5 * kShortestSegment / 2;

}  // namespace aloft::host::diagnose
