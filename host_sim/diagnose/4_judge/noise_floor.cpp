#include "diagnose/4_judge/noise_floor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "diagnose/1_input/time_gaps.hpp"
#include "diagnose/4_judge/low_pass_shape.hpp"
#include "diagnose/4_judge/noise_spectrum.hpp"

namespace aloft::host::diagnose {
namespace {

// Binomial coefficients of the k-th difference and the variance multiplier C(2k, k).
// For rates that are themselves first differences of white pose noise n (rate noise
// e = dn, var e = 2 var n), the k-th difference of e is the (k+1)-th of n: the factor
// relating it to var e is C(2k+2, k+1) / 2.
struct Difference {
  int order;
  std::array<double, 5> weights;
  double variance_factor;
  double variance_factor_differenced;
};
constexpr Difference kDifferences[] = {
    {2, {1, -2, 1, 0, 0}, 6.0, 10.0},
    {3, {1, -3, 3, -1, 0}, 20.0, 35.0},
    {4, {1, -4, 6, -4, 1}, 70.0, 126.0},
};

// Median of chi-square(1): median(x^2) = 0.45494 sigma^2 for Gaussian x.
constexpr double kMedianOfSquares = 0.454936;

double median(std::vector<double>& v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// The floor is never below the rounding noise of the data's resolution.
void hold_at_resolution(NoiseFloor& floor, const Flight& flight) {
  floor.resolution = reading_resolution(flight);
  const double rounding = floor.resolution / std::sqrt(12.0);
  for (int a = 0; a < 3; ++a) {
    if (floor.sigma(a) < rounding) {
      floor.sigma(a) = rounding;
      floor.method = "resolution";
    }
  }
}

// The spread where the sensor lay still is its noise as filtered and quantised, with no
// motion in it: nothing to separate, and it holds for a filtered gyro, whose differences
// of smooth data understate the noise.
NoiseFloor floor_from_rest(const Flight& flight) {
  NoiseFloor floor;
  floor.sigma = flight.rest_noise->cwiseMax(1e-6);
  floor.reliable = true;
  floor.method = "rest";
  hold_at_resolution(floor, flight);
  return floor;
}

// The spectrum's motion band ends at the first bin whose level is no more than
// kSteepHalfOctave times that at 1.5 times its frequency: a tumble's harmonics fall faster
// than that (12 dB over half an octave), a noise's spectrum slower (flat; 7 dB over half
// an octave past a 2nd-order low-pass's cutoff).
// Bins below kFirstNoiseBin hold the window's main lobe round the motion's lines.
constexpr double kSteepHalfOctave = 15.0;
constexpr std::size_t kFirstNoiseBin = 4;
constexpr std::size_t kPlateauBins = 5;  // the level below the band is the mean of these
// The differences understate a noise behind a low-pass (they see only the top of its
// band): where the spectrum's floor is more than kUnderstated times theirs, it is taken.
// White noise: the two agree within 15 % (the unfiltered flights of
// tests/diagnose/test_filtered_noise_floor.cpp); behind a low-pass at 0.4 of the rate
// (200 Hz at 1 kHz) the differences fall 5 times short.
constexpr double kUnderstated = 1.5;

struct SpectralFloor {
  Eigen::Vector3d sigma = Eigen::Vector3d::Zero();
  double correlation = 1.0;
  double cutoff_hz = 0.0;      // the low-pass fitted (0: none)
  int order = 0;               // its order (low_pass_shape.hpp; 0: none)
  const char* shape = "none";  // its shape: LowPassShape::name()
  double bend_s2 = 0.0;        // its bend of the motion: LowPassShape::bend_s2()
};

// The longest run of usable samples with no time gap inside.
std::vector<Eigen::Vector3d> longest_clean_run(const Flight& flight, const std::vector<char>& gap_after,
                                               double& rate_hz) {
  std::size_t best_first = 0, best_count = 0, first = 0;
  for (std::size_t k = 0; k <= flight.size(); ++k) {
    const bool ends = k == flight.size() || !flight.usable[k];
    if (!ends && !(k + 1 < flight.size() && gap_after[k])) continue;
    const std::size_t count = ends ? k - first : k + 1 - first;
    if (count > best_count) {
      best_first = first;
      best_count = count;
    }
    first = k + 1;
  }
  rate_hz = 0.0;
  if (best_count < 2) return {};
  rate_hz = static_cast<double>(best_count - 1) /
            (flight.time_s[best_first + best_count - 1] - flight.time_s[best_first]);
  return std::vector<Eigen::Vector3d>(
      flight.omega.begin() + static_cast<std::ptrdiff_t>(best_first),
      flight.omega.begin() + static_cast<std::ptrdiff_t>(best_first + best_count));
}

// The first bin above the motion's band (kSteepOctave), found on the three axes' sum
// smoothed over kPlateauBins; 0 when the spectrum has none.
std::size_t end_of_motion_band(const NoiseSpectrum& s) {
  const std::size_t bins = s.density.size();
  std::vector<double> smooth(bins, 0.0);
  for (std::size_t j = 0; j < bins; ++j) {
    const std::size_t from = j >= kPlateauBins / 2 ? j - kPlateauBins / 2 : 0;
    const std::size_t to = std::min(bins, j + kPlateauBins / 2 + 1);
    for (std::size_t i = from; i < to; ++i) smooth[j] += s.density[i].sum() / static_cast<double>(to - from);
  }
  for (std::size_t j = kFirstNoiseBin; j + j / 2 < bins; ++j) {
    if (smooth[j + j / 2] * kSteepHalfOctave >= smooth[j]) return j;
  }
  return 0;
}

// The bins the noise's shape is fitted on: from the motion band's end down to
// kFitDepth below the highest (beyond that lie rounding and the filter's zero at the
// Nyquist rate).
constexpr double kFitDepth = 1e-4;

// The low-pass's gain as the spectrum's bins see it (through the window's response,
// noise_spectrum.hpp), bins first .. last - 1.
std::vector<double> gain_in_bins(const NoiseSpectrum& s, std::size_t first, std::size_t last,
                                 const LowPassShape& shape) {
  return expected_densities(s, first, last, [&](double f) { return shape.gain(f); });
}

// Below the motion band's edge the bins hold the motion and the noise: the noise's
// shape, at the level the bins above give it, must not exceed them (the motion adds
// power, it never takes any away). Where the knee lies at or below the edge the bins
// above see only the roll-off, which fixes level x cutoff^4 and not each, and a cutoff
// fitted low (the variance goes as its -3rd power) puts the level below the edge above
// what the bins there hold; these bins rule it out. A bin of noise alone scatters about
// its expected density: 1 % of the time below 0.34-0.47 of it, 5 % below 0.49-0.60
// (medians of 5-6 segments, three axes summed: white noise behind 20 Hz, 0.82 s at 8 kHz
// and 0.98 s at 4 kHz), so a shape counts against a bin only by how far it exceeds
// kBelowEdgeSlack times the bin. Bins below kFirstBoundingBin are not used: the segment's
// quadratic takes part of the noise away there (bins 1 and 2 hold 0.47-0.48 and
// 0.87-0.90 of the density, bin 3 0.97-0.98).
constexpr double kBelowEdgeSlack = 2.0;
constexpr std::size_t kFirstBoundingBin = 3;

// The low-pass whose shape, as the bins see it, fits the three axes' spectrum above the
// motion band best (in log power, the level for each cutoff its best) and exceeds none of
// the bins below it kBelowEdgeSlack times (each excess's log counts as a misfit): for each
// shape of low_pass_shape.hpp, cutoffs on a log grid of 64 from kLowestCutoffBins bins to
// the Nyquist rate, and none after the Butterworth's. A PT1's cutoffs start at the motion
// band's edge: with its knee below the edge the bins above see only its 1/f^2 roll-off,
// which a motion's own tail has as well where the motion is not smooth (a knock, a string's
// buzz: the real racquet flights of 2025-01-16 fitted a PT1 at 6.2 Hz, the grid's lowest, at
// 3 of 6 flights, weighting them 30 times less), where a Butterworth's 1/f^4 is the sensor's.
// A flight controller's PT1 (50-500 Hz) lies far above a tumble's band. Measured on the grid of
// test_filtered_noise_floor.cpp (tuning and withheld seeds): worst x1.74 and x1.53 from 2 bins, x1.79 and
// x1.64 from 1 bin (a flight whose knee hides under the motion's band runs further down), x1.80 and x1.53
// with no bound below the edge.
constexpr double kLowestCutoffBins = 2.0;
// A PT2 (two PT1 stages: a flight controller's) is sought only where it can be told from a
// Butterworth, which falls as 1/f^4 as well and differs only at the knee: a PT2's bends
// over an octave or two (a quarter of the power at its cutoff, a Butterworth's half).
// - Only where the band above the motion spans kSoftKneeBand in frequency: over a narrower
//   band a PT2 fits a motion's steep tail as well as a sensor's roll-off. The real racquet
//   flights of 2025-01-16 (100 Hz, the band's edge at 9-12 Hz, a ratio of 4-5) fitted a PT2
//   at 22 and 36 Hz on 2 of 6 flights where their spectra fall by two decades an octave to
//   the Nyquist rate, a motion's fall, and their pooled shrink fell from 60 to 50 %; a
//   flight controller's log at 1-8 kHz spans 25 or more (test_filtered_scatter.cpp).
// - Its cutoffs start kSoftKneeAboveEdge times above the band's edge: a knee at the edge
//   is hidden under the motion. A Butterworth at 20 Hz (the edge at 16-23 Hz at 1-8 kHz)
//   was fitted by a PT2 at 1.00-1.39 times the edge in 30 flights of the grid of
//   test_filtered_scatter.cpp (tuning and fresh seeds) and then outfitted its Butterworth
//   in half of them, where the PT2s and PT1 pairs at 50-400 Hz came out at 1.41-37 times
//   the edge.
constexpr double kSoftKneeBand = 10.0;
constexpr double kSoftKneeAboveEdge = 1.5;
// Bins fitted hold at least this many times the rounding's density (rounding_density,
// below): nearer it, a bin's median over a few segments less the rounding scatters about
// zero, and the bins that come out above it, kept, bend the roll-off flat.
constexpr double kAboveRounding = 10.0;
double shape_misfit(const NoiseSpectrum& s, std::size_t first, std::size_t edge,
                    const std::vector<std::size_t>& bins, const std::vector<double>& gain) {
  double mean = 0.0, squares = 0.0;
  for (std::size_t j : bins) {
    const double r = std::log(s.density[j].sum() / gain[j - first]);
    mean += r;
    squares += r * r;
  }
  const double n = static_cast<double>(bins.size());
  double misfit = squares - mean * mean / n;
  const double log_level = mean / n;
  for (std::size_t j = first; j < edge; ++j) {
    const double excess = log_level + std::log(gain[j - first] / kBelowEdgeSlack / s.density[j].sum());
    if (excess > 0.0) misfit += excess * excess;
  }
  return misfit;
}

struct FittedShape {
  LowPassShape shape;
  double misfit = -1.0;  // < 0: none sought
};

// The cutoff of one kind of low-pass that fits the bins best (a tie keeps the lower).
FittedShape best_cutoff(const NoiseSpectrum& s, std::size_t edge, LowPassShape::Kind kind,
                        const std::vector<std::size_t>& bins) {
  using Kind = LowPassShape::Kind;
  const std::size_t last = s.density.size() - 1, first = std::min(kFirstBoundingBin, edge);
  const double low = kLowestCutoffBins * s.bin_hz, high = 0.5 * s.sample_hz;
  const double from = kind == Kind::butterworth   ? low
                      : kind == Kind::first_order ? std::max(low, edge * s.bin_hz)
                                                  : std::max(low, kSoftKneeAboveEdge * edge * s.bin_hz);
  const std::vector<double> frequencies = response_frequencies(s, first, last);
  std::vector<double> abscissae(frequencies.size()), fine(frequencies.size());
  for (std::size_t k = 0; k < frequencies.size(); ++k)
    abscissae[k] = LowPassShape::abscissa(kind, frequencies[k], s.sample_hz);
  FittedShape best{LowPassShape(kind, 0.0, s.sample_hz)};
  for (int i = 0; i <= 64; ++i) {
    if (i == 64 && kind != Kind::butterworth) break;  // "no low-pass" is tried once
    const LowPassShape shape(kind, i == 64 ? 0.0 : from * std::pow(high / from, i / 63.0), s.sample_hz);
    for (std::size_t k = 0; k < fine.size(); ++k) fine[k] = shape.gain_at(abscissae[k]);
    const double misfit = shape_misfit(s, first, edge, bins, densities_seen(s, fine));
    if (best.misfit < 0.0 || misfit < best.misfit) best = {shape, misfit};
  }
  return best;
}

// Where a PT2 and the best of the other shapes fit the bins about as well (misfits within
// a factor kShapesToldApart), the bins do not tell which the gyro sits behind; the floor
// then takes the mean, in log, of the two floors, weighted linearly in the log of the
// misfits' ratio (the PT2's share 1/2 at equal misfits, 1 at kShapesToldApart times less,
// 0 at as many times more). Behind a knee hidden under the motion the two shapes' correlations
// differ by a factor of about 1.4 (2 fs / (pi fc) against fs / (2.2 fc)), so the mean is off
// by at most its square root whichever the gyro has. Measured on the grid of
// test_filtered_scatter.cpp: a Butterworth at 50 Hz gave misfit ratios (PT2 over Butterworth)
// of 0.82-3.4 at 1-8 kHz, a PT2 at 50 Hz at 4 kHz 0.60-1.18; every PT2 and PT1 pair at
// 100-400 Hz, and at 50 Hz at 1 and 8 kHz, under 0.87.
constexpr double kShapesToldApart = 1.25;
double pt2_share(const FittedShape& pt2, const FittedShape& other) {
  if (pt2.misfit < 0.0) return 0.0;
  if (other.misfit <= 0.0) return pt2.misfit <= 0.0 ? 0.5 : 0.0;
  if (pt2.misfit <= 0.0) return 1.0;
  const double share = 0.5 - std::log(pt2.misfit / other.misfit) / (2.0 * std::log(kShapesToldApart));
  return std::clamp(share, 0.0, 1.0);
}

struct FittedLowPass {
  LowPassShape other;      // the Butterworth or PT1 that fits best (cutoff 0: no low-pass)
  LowPassShape pt2;        // the PT2 that fits best (cutoff 0: none sought)
  double pt2_share = 0.0;  // its share of the floor (pt2_share)
};

FittedLowPass fitted_low_pass(const NoiseSpectrum& s, std::size_t edge, double rounding) {
  std::vector<std::size_t> bins;
  double highest = 0.0;
  const std::size_t last = s.density.size() - 1;
  for (std::size_t j = edge; j < last; ++j) highest = std::max(highest, s.density[j].sum());
  for (std::size_t j = edge; j < last; ++j) {
    if (s.density[j].sum() >= kFitDepth * highest && s.density[j].sum() > 3.0 * kAboveRounding * rounding)
      bins.push_back(j);
  }
  using Kind = LowPassShape::Kind;
  const FittedShape butterworth = best_cutoff(s, edge, Kind::butterworth, bins);
  const FittedShape first_order = best_cutoff(s, edge, Kind::first_order, bins);
  const FittedShape& other = first_order.misfit < butterworth.misfit ? first_order : butterworth;
  const double band = 0.5 * s.sample_hz / (static_cast<double>(edge) * s.bin_hz);
  const FittedShape pt2 =
      band >= kSoftKneeBand ? best_cutoff(s, edge, Kind::two_first_order, bins) : FittedShape{other.shape};
  return {other.shape, pt2.shape, pt2_share(pt2, other)};
}

// Readings rounded to a step q carry a white noise of variance q^2 / 12 on each axis
// besides the filtered one, flat to the Nyquist rate: one-sided density 2 (q^2 / 12) / fs.
// Behind a low-pass the filtered noise falls below it well before the Nyquist rate (a
// flight controller's 1/16.4 deg/s behind a 100 Hz Butterworth at 1 kHz: past about
// 400 Hz), where a shape fitted to the bins as they are would read the rounding's plateau
// as a first-order roll-off, 40 times the correlation there is. It is taken off each bin,
// and bins that hold less than twice it (three axes summed) are not fitted.
double rounding_density(double resolution, double sample_hz) {
  return 2.0 * resolution * resolution / 12.0 / sample_hz;
}
NoiseSpectrum without_rounding(NoiseSpectrum s, double rounding) {
  for (Eigen::Vector3d& d : s.density) d = (d.array() - rounding).max(0.0).matrix();
  return s;
}

// The filter's bend of the motion (LowPassShape::bend_s2) is its second-order term in
// 2 pi f RC, f the motion's frequencies: it is given only where the cutoff lies at least
// kBendAboveEdge times above the motion band's edge, where 2 pi f RC is under about 2/3 and the
// terms after it are smaller still. At the edge it is not: a PT1 at 20 Hz behind 100 Hz
// readings, fitted at the edge, bent by it, made its flights disagree more (scatter 7.9 -> 11.9,
// test_filtered_scatter.cpp's tuning seeds), where at 50 Hz behind 4 kHz (2-3 times the edge)
// the bend took a session's scatter from 3.9 to 1.6.
constexpr double kBendAboveEdge = 1.5;

// The noise's variance per axis behind `filter`: its power above the motion's band, and
// below it the filter's shape at the level the bins above the band give it, and the
// rounding's; and its correlation, the density at low frequencies over a white noise's of
// the same variance.
SpectralFloor floor_behind(const NoiseSpectrum& s, std::size_t edge, double rounding,
                           const LowPassShape& filter) {
  // The level: the bins' power over the shape's, summed over the band above the motion
  // to kFitDepth (each bin weighed by the shape, so the flat part counts most).
  Eigen::Vector3d power = Eigen::Vector3d::Zero(), variance = Eigen::Vector3d::Zero();
  double shape = 0.0, below = 0.0;
  const std::vector<double> seen = gain_in_bins(s, edge, s.density.size() - 1, filter);
  for (std::size_t j = edge; j + 1 < s.density.size(); ++j) {
    if (seen[j - edge] < kFitDepth) break;
    power += s.density[j];
    shape += seen[j - edge];
  }
  const Eigen::Vector3d level = power / shape;
  // The variance from the fitted shape over the whole band (the bins themselves hold the
  // motion's harmonics too, which outweigh a quiet gyro's noise behind a 20 Hz low-pass).
  for (std::size_t j = 0; j < s.density.size(); ++j) {
    const double width = (j == 0 || j + 1 == s.density.size()) ? 0.5 : 1.0;
    below += width * filter.gain(j * s.bin_hz) * s.bin_hz;
  }
  variance = (level * below).array() + rounding * 0.5 * s.sample_hz;
  SpectralFloor out;
  out.sigma = variance.cwiseSqrt();
  out.correlation = std::max(1.0, (level.sum() + 3.0 * rounding) * 0.5 * s.sample_hz / variance.sum());
  out.cutoff_hz = filter.cutoff_hz();
  out.order = filter.cutoff_hz() > 0.0 ? filter.order() : 0;
  out.shape = filter.cutoff_hz() > 0.0 ? filter.name() : "none";
  out.bend_s2 = filter.cutoff_hz() >= kBendAboveEdge * edge * s.bin_hz ? filter.bend_s2() : 0.0;
  return out;
}

// The floor behind the fitted low-pass; where a PT2 fits about as well as the other shapes
// (pt2_share), the mean of the two floors in log, named after the larger share.
std::optional<SpectralFloor> floor_from_spectrum(const Flight& flight, const std::vector<char>& gap_after,
                                                 double resolution) {
  double rate_hz = 0.0;
  const std::vector<Eigen::Vector3d> run = longest_clean_run(flight, gap_after, rate_hz);
  const NoiseSpectrum all = welch_spectrum(run, rate_hz);
  const std::size_t edge = all.density.empty() ? 0 : end_of_motion_band(all);
  if (edge == 0 || edge + kPlateauBins > all.density.size()) return std::nullopt;
  // An impulse's step shows most over the octave just above the motion's band.
  const double rounding = rounding_density(resolution, rate_hz);
  const NoiseSpectrum s = without_rounding(
      without_outlying_segments(all, edge, std::min(2 * edge, all.density.size())), rounding);
  const FittedLowPass fitted = fitted_low_pass(s, edge, rounding);
  SpectralFloor out = floor_behind(s, edge, rounding, fitted.other);
  if (fitted.pt2_share > 0.0) {
    const SpectralFloor pt2 = floor_behind(s, edge, rounding, fitted.pt2);
    const double w = fitted.pt2_share;
    const Eigen::Vector3d sigma = (w * pt2.sigma.array().log() + (1.0 - w) * out.sigma.array().log()).exp();
    const double correlation =
        std::exp(w * std::log(pt2.correlation) + (1.0 - w) * std::log(out.correlation));
    const double bend_s2 = w * pt2.bend_s2 + (1.0 - w) * out.bend_s2;
    if (w > 0.5) out = pt2;
    out.sigma = sigma;
    out.correlation = correlation;
    out.bend_s2 = bend_s2;
  }
  return out;
}

// The spectrum's correlation and the low-pass it was read behind, into `floor`.
void take_correlation(NoiseFloor& floor, const SpectralFloor& spectral) {
  floor.correlation = spectral.correlation;
  floor.low_pass_hz = spectral.cutoff_hz;
  floor.low_pass_order = spectral.order;
  floor.low_pass_shape = spectral.shape;
  floor.low_pass_bend_s2 = spectral.bend_s2;
}

// A log that lay still gives the noise's spread as it is (floor_from_rest), but not how
// correlated it is: behind a flight controller's low-pass its readings are correlated over
// tens of samples, and a fit that counted each as independent weighed its evidence as many
// times too strongly (a PT1 at 100 Hz behind 1 kHz, 400 Hz behind 4 kHz and a Butterworth at
// 20 Hz behind 100 Hz, still before the throw: their flights disagreed, scatter 3.3-5.8,
// test_filtered_scatter.cpp). The correlation, the filter and its bend come from the flight's
// spectrum as without rest (floor_from_spectrum), for logs at kFastGyro_hz and above. Below,
// the phone's rates (100-400 Hz), it is left at 1: taken there it moved 14 of the 65 reports of
// tests/diagnose/make_reports.sh, the real racquet's second session's verdict among them (gyro
// scale to inertia moments), and practice3/T00's tensor report for the worse (its nominal
// Iy/Ix, right, then outside the interval): the phone's rules were set with it at 1.
constexpr double kFastGyro_hz = 1000.0;
// The spectrum's correlation is taken where it exceeds this: a white noise's reads 1 (the 1 kHz
// flights with rest of ../shared/data/practice2/C00-C03: 1 + 1e-15, a Butterworth fitted at the
// Nyquist rate), the filters of test_filtered_scatter.cpp's grid at 1-8 kHz 4 and more.
constexpr double kCorrelatedAtRest = 1.5;

NoiseFloor floor_from_rest_and_spectrum(const Flight& flight) {
  NoiseFloor floor = floor_from_rest(flight);
  if (!flight.gyro_input || flight.rates_from_differences || flight.rate_hz() < kFastGyro_hz) return floor;
  const std::optional<SpectralFloor> spectral =
      floor_from_spectrum(flight, steps_followed_by_gap(flight.time_s), reading_resolution(flight));
  if (spectral && spectral->cutoff_hz > 0.0 && spectral->correlation >= kCorrelatedAtRest)
    take_correlation(floor, *spectral);
  return floor;
}

}  // namespace

NoiseFloor estimate_noise_floor(const Flight& flight) {
  if (flight.rest_noise) return floor_from_rest_and_spectrum(flight);
  NoiseFloor best;
  const std::vector<char> gap_after = steps_followed_by_gap(flight.time_s);
  const std::size_t n = flight.size();
  double best_total = -1.0;
  for (const Difference& d : kDifferences) {
    const std::size_t span = static_cast<std::size_t>(d.order) + 1;
    if (n < span) continue;
    std::array<std::vector<double>, 3> squares;
    for (std::size_t k = 0; k + span <= n; ++k) {
      bool clean = true;
      for (std::size_t j = 0; j < span; ++j) {
        if (!flight.usable[k + j] || (j + 1 < span && gap_after[k + j])) clean = false;
      }
      if (!clean) continue;
      Eigen::Vector3d value = Eigen::Vector3d::Zero();
      for (std::size_t j = 0; j < span; ++j) value += d.weights[j] * flight.omega[k + j];
      for (int a = 0; a < 3; ++a) squares[static_cast<std::size_t>(a)].push_back(value(a) * value(a));
    }
    if (squares[0].size() < 10) continue;
    Eigen::Vector3d sigma;
    for (int a = 0; a < 3; ++a) {
      const double m = median(squares[static_cast<std::size_t>(a)]);
      const double factor = flight.rates_from_differences ? d.variance_factor_differenced : d.variance_factor;
      sigma(a) = std::max(std::sqrt(m / kMedianOfSquares / factor), 1e-6);
    }
    // A smooth motion only ever adds to a difference's spread, so the smallest estimate
    // is the least contaminated by the motion itself.
    const double total = sigma.squaredNorm();
    if (best_total < 0.0 || total < best_total) {
      best_total = total;
      best.sigma = sigma;
      best.difference_order = d.order;
      best.reliable = squares[0].size() >= 20;
    }
  }
  if (flight.gyro_input && !flight.rates_from_differences) {
    const std::optional<SpectralFloor> spectral =
        floor_from_spectrum(flight, gap_after, reading_resolution(flight));
    if (spectral && spectral->sigma.norm() > kUnderstated * best.sigma.norm()) {
      best.sigma = spectral->sigma.cwiseMax(1e-6);
      best.reliable = true;
      best.method = "spectrum";
      take_correlation(best, *spectral);
    }
  }
  hold_at_resolution(best, flight);
  return best;
}

double reading_resolution(const Flight& flight) {
  std::array<double, 3> steps{0.0, 0.0, 0.0};
  for (int a = 0; a < 3; ++a) {
    std::vector<double> values;
    for (std::size_t k = 0; k < flight.size(); ++k) {
      if (flight.usable[k]) values.push_back(flight.omega[k](a));
    }
    std::sort(values.begin(), values.end());
    double step = 0.0;
    for (std::size_t k = 1; k < values.size(); ++k) {
      const double d = values[k] - values[k - 1];
      // Steps below 1e-12 rad/s are the binary rounding of one decimal value, not a step.
      if (d > 1e-12 && (step == 0.0 || d < step)) step = d;
    }
    steps[static_cast<std::size_t>(a)] = step;
  }
  std::sort(steps.begin(), steps.end());
  return steps[1];
}

}  // namespace aloft::host::diagnose
