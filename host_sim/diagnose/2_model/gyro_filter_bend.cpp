#include "diagnose/2_model/gyro_filter_bend.hpp"

#include <algorithm>
#include <cstddef>

namespace aloft::host::diagnose {
namespace {

// The second derivative's half span: the integration's longest step (5 ms, flight_model.cpp),
// so each derivative spans whole cubic pieces. A tumble's motion at f changes its second
// derivative over 1 / f (100 ms at 10 Hz): the three points then err by (2 pi f h)^2 / 12,
// under 1 %.
constexpr double kBendSpan = 0.005;

// The sample nearest time t among time_s (increasing).
std::size_t nearest(const std::vector<double>& time_s, double t) {
  const auto at = std::lower_bound(time_s.begin(), time_s.end(), t);
  if (at == time_s.begin()) return 0;
  if (at == time_s.end()) return time_s.size() - 1;
  const std::size_t k = static_cast<std::size_t>(at - time_s.begin());
  return t - time_s[k - 1] <= time_s[k] - t ? k - 1 : k;
}

}  // namespace

void bend_by_gyro_filter(const Flight& flight, std::vector<Eigen::Vector3d>& readings) {
  const double bend = flight.gyro_filter_bend_s2;
  const std::vector<double>& t = flight.time_s;
  if (bend <= 0.0 || t.size() < 3 || t.back() - t.front() < 2.0 * kBendSpan) return;
  std::vector<Eigen::Vector3d> second(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    const double centre = std::clamp(t[k], t.front() + kBendSpan, t.back() - kBendSpan);
    const std::size_t m = std::clamp<std::size_t>(nearest(t, centre), 1, t.size() - 2);
    const std::size_t a = std::min(nearest(t, t[m] - kBendSpan), m - 1);
    const std::size_t b = std::max(nearest(t, t[m] + kBendSpan), m + 1);
    const Eigen::Vector3d rise_before = (readings[m] - readings[a]) / (t[m] - t[a]);
    const Eigen::Vector3d rise_after = (readings[b] - readings[m]) / (t[b] - t[m]);
    second[k] = 2.0 * (rise_after - rise_before) / (t[b] - t[a]);
  }
  for (std::size_t k = 0; k < t.size(); ++k) readings[k] += bend * second[k];
}

}  // namespace aloft::host::diagnose
