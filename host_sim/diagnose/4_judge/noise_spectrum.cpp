#include "diagnose/4_judge/noise_spectrum.hpp"

#include <Eigen/QR>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>

namespace aloft::host::diagnose {
namespace {

constexpr double kPi = 3.14159265358979323846;

// In-place radix-2 FFT (size a power of two).
void fft(std::vector<std::complex<double>>& x) {
  const std::size_t n = x.size();
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(x[i], x[j]);
  }
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const double angle = -2.0 * kPi / static_cast<double>(len);
    const std::complex<double> step(std::cos(angle), std::sin(angle));
    for (std::size_t i = 0; i < n; i += len) {
      std::complex<double> w(1.0, 0.0);
      for (std::size_t k = 0; k < len / 2; ++k) {
        const std::complex<double> u = x[i + k], v = x[i + k + len / 2] * w;
        x[i + k] = u + v;
        x[i + k + len / 2] = u - v;
        w *= step;
      }
    }
  }
}

std::vector<double> blackman_harris(std::size_t n) {
  std::vector<double> w(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double x = 2.0 * kPi * static_cast<double>(k) / static_cast<double>(n);
    w[k] = 0.35875 - 0.48829 * std::cos(x) + 0.14128 * std::cos(2 * x) - 0.01168 * std::cos(3 * x);
  }
  return w;
}

// The segment less its least-squares quadratic in k (centred, so the normal equations
// stay well conditioned).
std::vector<double> without_quadratic(const std::vector<double>& y) {
  const std::size_t n = y.size();
  Eigen::MatrixXd a(static_cast<Eigen::Index>(n), 3);
  Eigen::VectorXd b(static_cast<Eigen::Index>(n));
  const double mid = 0.5 * static_cast<double>(n - 1);
  for (std::size_t k = 0; k < n; ++k) {
    const double u = (static_cast<double>(k) - mid) / mid;
    a.row(static_cast<Eigen::Index>(k)) << 1.0, u, u * u;
    b(static_cast<Eigen::Index>(k)) = y[k];
  }
  const Eigen::VectorXd c = a.colPivHouseholderQr().solve(b);
  const Eigen::VectorXd r = b - a * c;
  return std::vector<double>(r.data(), r.data() + r.size());
}

// The longest power of two that gives at least four half-overlapping segments (n >= 2.5
// lengths; 4 to 9 segments). The window's main lobe spans +-4 bins, so the bins' width
// decides how far above the tumble's harmonics their smear reaches: at 8 kHz a flight of
// 0.82 s in 1024-sample segments (7.8 Hz bins, at least six segments as before) smeared
// them to 31-47 Hz, past a 20 Hz low-pass's knee, whose cutoff, fitted on the roll-off
// alone, came out 15.6 Hz for 20 on half of the noise-only runs; in 2048 (3.9 Hz) the
// knee shows above them. An impulse's step, in one or two of these fewer segments, is
// taken out by without_outlying_segments before the cutoff is fitted.
std::size_t segment_length(std::size_t n) {
  std::size_t length = static_cast<std::size_t>(kShortestSegment);
  while (5 * length <= n) length *= 2;
  return length;
}

// The median of m segments' powers (the mean of the middle two where m is even).
double median_of(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  if (v.size() % 2 == 1) return *mid;
  return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

// The expected k-th smallest of m independent exponentials of mean 1: the sum of 1/i for
// i from m - k + 1 to m (Renyi's representation of their order statistics).
double expected_order_statistic(std::size_t k, std::size_t m) {
  double sum = 0.0;
  for (std::size_t i = m - k + 1; i <= m; ++i) sum += 1.0 / static_cast<double>(i);
  return sum;
}

// A bin's power in one segment of Gaussian noise is exponentially distributed about its
// mean (two Gaussian parts), so its median over m segments has this expected value for
// a unit mean: ln 2 for many segments, but 0.783 for 6 and 0.833 for 4 (ln 2 in its place
// overstated the power by 13 and 20 %). Half-overlapping segments under a
// Blackman-Harris window are as good as independent (their powers correlate by well
// under 1 %).
double expected_median_of_unit_exponentials(std::size_t m) {
  if (m % 2 == 1) return expected_order_statistic((m + 1) / 2, m);
  return 0.5 * (expected_order_statistic(m / 2, m) + expected_order_statistic(m / 2 + 1, m));
}

// The window's power response |W(f)|^2 near 0 (zero-padded to kResponseSteps points a
// bin), normalised to sum 1.
std::vector<double> window_response(const std::vector<double>& window) {
  const std::size_t steps = static_cast<std::size_t>(kResponseSteps);
  std::vector<std::complex<double>> padded(window.size() * steps, 0.0);
  for (std::size_t k = 0; k < window.size(); ++k) padded[k] = window[k];
  fft(padded);
  const std::size_t reach = static_cast<std::size_t>(kResponseBins) * steps;
  std::vector<double> response(2 * reach + 1);
  double sum = 0.0;
  for (std::size_t i = 0; i < response.size(); ++i) {
    const std::size_t at = (padded.size() + i - reach) % padded.size();
    response[i] = std::norm(padded[at]);
    sum += response[i];
  }
  for (double& r : response) r /= sum;
  return response;
}

// Each bin's median over the kept segments, over its expected value for a unit mean.
std::vector<Eigen::Vector3d> median_density(const std::vector<std::vector<Eigen::Vector3d>>& segment_power,
                                            const std::vector<char>& kept) {
  const std::size_t count = static_cast<std::size_t>(std::count(kept.begin(), kept.end(), 1));
  const double median_over_mean = expected_median_of_unit_exponentials(count);
  const std::size_t bins = segment_power.front().size();
  std::vector<Eigen::Vector3d> density(bins, Eigen::Vector3d::Zero());
  std::vector<double> values;
  for (Eigen::Index a = 0; a < 3; ++a) {
    for (std::size_t j = 0; j < bins; ++j) {
      values.clear();
      for (std::size_t m = 0; m < segment_power.size(); ++m)
        if (kept[m]) values.push_back(segment_power[m][j](a));
      density[j](a) = median_of(values) / median_over_mean;
    }
  }
  return density;
}

}  // namespace

std::vector<double> response_frequencies(const NoiseSpectrum& s, std::size_t first, std::size_t last) {
  const std::ptrdiff_t steps = kResponseSteps, reach = static_cast<std::ptrdiff_t>(s.response.size() / 2);
  const std::ptrdiff_t from = static_cast<std::ptrdiff_t>(first) * steps - reach;
  std::vector<double> fine(
      static_cast<std::size_t>(static_cast<std::ptrdiff_t>(last - first) * steps + 2 * reach));
  for (std::size_t i = 0; i < fine.size(); ++i) {
    const double bins = static_cast<double>(from + static_cast<std::ptrdiff_t>(i)) / kResponseSteps;
    fine[i] = std::abs(bins) * s.bin_hz;
  }
  return fine;
}

std::vector<double> densities_seen(const NoiseSpectrum& s, const std::vector<double>& true_density) {
  const std::size_t steps = static_cast<std::size_t>(kResponseSteps);
  std::vector<double> out((true_density.size() - 2 * (s.response.size() / 2)) / steps, 0.0);
  for (std::size_t j = 0; j < out.size(); ++j) {
    const std::size_t centre = j * steps;
    for (std::size_t i = 0; i < s.response.size(); ++i) out[j] += s.response[i] * true_density[centre + i];
  }
  return out;
}

NoiseSpectrum welch_spectrum(const std::vector<Eigen::Vector3d>& readings, double sample_hz) {
  NoiseSpectrum s;
  const std::size_t n = readings.size();
  if (n < static_cast<std::size_t>(kShortestSpectrum) || !(sample_hz > 0.0)) return s;
  const std::size_t length = segment_length(n);
  const std::vector<double> window = blackman_harris(length);
  double window_power = 0.0;
  for (double w : window) window_power += w * w;
  s.sample_hz = sample_hz;
  s.response = window_response(window);
  s.bin_hz = sample_hz / static_cast<double>(length);
  const std::size_t bins = length / 2 + 1;
  std::vector<std::complex<double>> x(length);
  // Each segment's power in each bin, per axis.
  for (std::size_t start = 0; start + length <= n; start += length / 2) {
    std::vector<Eigen::Vector3d> power(bins, Eigen::Vector3d::Zero());
    for (std::size_t a = 0; a < 3; ++a) {
      std::vector<double> y(length);
      for (std::size_t k = 0; k < length; ++k) y[k] = readings[start + k](static_cast<Eigen::Index>(a));
      y = without_quadratic(y);
      for (std::size_t k = 0; k < length; ++k) x[k] = y[k] * window[k];
      fft(x);
      for (std::size_t j = 0; j < bins; ++j) {
        const double one_sided = (j == 0 || j == length / 2) ? 1.0 : 2.0;
        power[j](static_cast<Eigen::Index>(a)) = one_sided * std::norm(x[j]) / (sample_hz * window_power);
      }
    }
    s.segment_power.push_back(std::move(power));
  }
  s.segments = static_cast<int>(s.segment_power.size());
  s.density = median_density(s.segment_power, std::vector<char>(s.segment_power.size(), 1));
  return s;
}

NoiseSpectrum without_outlying_segments(const NoiseSpectrum& s, std::size_t first, std::size_t last) {
  std::vector<double> band(s.segment_power.size(), 0.0);
  for (std::size_t m = 0; m < band.size(); ++m) {
    for (std::size_t j = first; j < last; ++j) band[m] += s.segment_power[m][j].sum();
  }
  const double typical = median_of(band);
  std::vector<char> kept(band.size(), 0);
  std::size_t count = 0;
  for (std::size_t m = 0; m < band.size(); ++m) {
    kept[m] = band[m] <= kOutlyingBandPower * typical;
    count += static_cast<std::size_t>(kept[m]);
  }
  NoiseSpectrum out = s;
  if (count == band.size() || count < static_cast<std::size_t>(kFewestKeptSegments)) return out;
  out.density = median_density(s.segment_power, kept);
  out.segments = static_cast<int>(count);
  return out;
}

}  // namespace aloft::host::diagnose
