#include "diagnose/1_input/rest_periods.hpp"

#include <algorithm>
#include <cmath>

namespace aloft::host::diagnose {
namespace {

// A slow motion (a hand holding the sensor, a body rolling to a stop) spreads the readings
// far more than it moves them from one sample to the next; noise, even a low-passed
// one, moves them about as much as it spreads them (white: RMS step = √2 σ). Still means
// the spread is at most kMotionRatio times the one the steps imply, on every axis.
constexpr double kMotionRatio = 2.0;
bool still(const ImuLog& log, std::size_t first, std::size_t last, double from, double to,
           const Eigen::Vector3d& spread) {
  Eigen::Vector3d steps = Eigen::Vector3d::Zero();
  std::size_t count = 0;
  for (std::size_t k = first; k < last; ++k) {
    if (log.time_s[k] < from || log.time_s[k + 1] > to) continue;
    steps += (log.gyro_rad_s[k + 1] - log.gyro_rad_s[k]).cwiseAbs2();
    ++count;
  }
  if (count == 0) return false;
  const Eigen::Vector3d from_steps = (steps / (2.0 * static_cast<double>(count))).cwiseSqrt();
  return (spread.array() <= kMotionRatio * from_steps.array()).all();
}

// The period [from, to) of the log's samples without the run's edges, or nothing when
// it is too short.
std::optional<RestPeriod> period_of(const ImuLog& log, std::size_t first, std::size_t last) {
  const double from = log.time_s[first] + kRestEdge_s, to = log.time_s[last] - kRestEdge_s;
  if (to - from < kMinimumRest_s) return std::nullopt;
  RestPeriod p;
  p.from_s = from;
  p.to_s = to;
  p.still_until_s = log.time_s[last];
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), squares = Eigen::Vector3d::Zero();
  for (std::size_t k = first; k <= last; ++k) {
    if (log.time_s[k] < from || log.time_s[k] > to) continue;
    sum += log.gyro_rad_s[k];
    squares += log.gyro_rad_s[k].cwiseAbs2();
    ++p.samples;
  }
  const double n = static_cast<double>(p.samples);
  if (p.samples < 20) return std::nullopt;
  const Eigen::Vector3d mean = sum / n;
  p.sigma = (squares / n - mean.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt() * std::sqrt(n / (n - 1.0));
  if (!still(log, first, last, from, to, p.sigma)) return std::nullopt;
  return p;
}

}  // namespace

std::vector<RestPeriod> find_rest_periods(const ImuLog& log) {
  std::vector<RestPeriod> periods;
  const std::size_t n = std::min(log.time_s.size(), log.gyro_rad_s.size());
  std::size_t k = 0;
  while (k < n) {
    if (!(log.gyro_rad_s[k].norm() < kStillRate_rad_s)) {
      ++k;
      continue;
    }
    std::size_t last = k;
    while (last + 1 < n && log.gyro_rad_s[last + 1].norm() < kStillRate_rad_s) ++last;
    if (auto p = period_of(log, k, last)) periods.push_back(*p);
    k = last + 1;
  }
  return periods;
}

std::optional<RestNoise> rest_noise(const std::vector<RestPeriod>& periods) {
  if (periods.empty()) return std::nullopt;
  double quietest = INFINITY;
  for (const RestPeriod& p : periods) quietest = std::min(quietest, p.sigma.norm());
  RestNoise out;
  Eigen::Vector3d variance_sum = Eigen::Vector3d::Zero();
  std::size_t samples = 0;
  for (const RestPeriod& p : periods) {
    if (p.sigma.norm() > 1.5 * quietest) continue;
    variance_sum += p.sigma.cwiseAbs2() * static_cast<double>(p.samples);
    samples += p.samples;
    out.seconds += p.to_s - p.from_s;
    ++out.periods;
  }
  out.sigma = (variance_sum / static_cast<double>(samples)).cwiseSqrt();
  return out;
}

bool released_from_rest(const std::vector<RestPeriod>& periods, double start_s) {
  for (const RestPeriod& p : periods) {
    if (p.still_until_s <= start_s + kRestEdge_s && p.still_until_s >= start_s - kSpinUp_s) return true;
  }
  return false;
}

}  // namespace aloft::host::diagnose
