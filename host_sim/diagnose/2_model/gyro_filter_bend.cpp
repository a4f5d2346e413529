#include "diagnose/2_model/gyro_filter_bend.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace aloft::host::diagnose {
namespace {

// The second derivative's half span: the integration's longest step (5 ms, flight_model.cpp),
// so each derivative spans whole cubic pieces. A tumble's motion at f changes its second
// derivative over 1 / f (100 ms at 10 Hz): the three points then err by (2 pi f h)^2 / 12,
// under 1 %.
constexpr double kBendSpan = 0.005;

// The position in `run` (samples in time order) nearest time `target`, searched onwards from
// `from`: the targets of one pass only grow, so each pass is linear in the run's length.
std::size_t nearest_onwards(const std::vector<double>& t, const std::vector<std::size_t>& run,
                            std::size_t from, double target) {
  while (from + 1 < run.size() && std::abs(t[run[from + 1]] - target) <= std::abs(t[run[from]] - target))
    ++from;
  return from;
}

// The bend of the samples `run` lists, from their own readings. Each prediction bends its
// readings (thousands a fit), so no search and no allocation a call: the second derivatives
// go to a buffer kept per thread.
void bend_run(const std::vector<double>& t, const std::vector<std::size_t>& run, double bend,
              std::vector<Eigen::Vector3d>& readings) {
  const std::size_t n = run.size();
  if (n < 3 || t[run.back()] - t[run.front()] < 2.0 * kBendSpan) return;
  thread_local std::vector<Eigen::Vector3d> second;
  second.resize(n);
  std::size_t before = 0, centre = 0, after = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double at = std::clamp(t[run[i]], t[run.front()] + kBendSpan, t[run.back()] - kBendSpan);
    centre = nearest_onwards(t, run, centre, at);
    const std::size_t m = std::clamp<std::size_t>(centre, 1, n - 2);
    before = nearest_onwards(t, run, before, t[run[m]] - kBendSpan);
    after = nearest_onwards(t, run, after, t[run[m]] + kBendSpan);
    const std::size_t a = run[std::min(before, m - 1)], b = run[std::max(after, m + 1)], c = run[m];
    const Eigen::Vector3d rise_before = (readings[c] - readings[a]) / (t[c] - t[a]);
    const Eigen::Vector3d rise_after = (readings[b] - readings[c]) / (t[b] - t[c]);
    second[i] = 2.0 * (rise_after - rise_before) / (t[b] - t[a]);
  }
  for (std::size_t i = 0; i < n; ++i) readings[run[i]] += bend * second[i];
}

}  // namespace

void bend_by_gyro_filter(const Flight& flight, std::vector<Eigen::Vector3d>& readings, ReadSamples read) {
  const double bend = flight.gyro_filter_bend_s2;
  if (bend <= 0.0) return;
  const std::vector<double>& t = flight.time_s;
  thread_local std::vector<std::size_t> run;  // kept per thread, as bend_run's buffer
  run.clear();
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!read.wanted(k)) continue;
    if (!run.empty() && t[k] - t[run.back()] > kBendSpan) {
      bend_run(t, run, bend, readings);
      run.clear();
    }
    run.push_back(k);
  }
  bend_run(t, run, bend, readings);
}

}  // namespace aloft::host::diagnose
