#include "diagnose/4_judge/noise_floor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "diagnose/1_input/time_gaps.hpp"

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

}  // namespace

NoiseFloor estimate_noise_floor(const Flight& flight) {
  if (flight.rest_noise) return floor_from_rest(flight);
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
