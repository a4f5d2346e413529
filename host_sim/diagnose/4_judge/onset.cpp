#include "diagnose/4_judge/onset.hpp"

#include <algorithm>

namespace aloft::host::diagnose {

std::optional<double> cusum_onset(const Flight& flight, const std::vector<Eigen::Vector3d>& readings,
                                  const Eigen::Vector3d& inverse_sigma) {
  constexpr double kDrift = 0.5, kAlarm = 15.0;
  double sum = 0.0;
  std::size_t start = 0;
  for (std::size_t k = 0; k < flight.size(); ++k) {
    if (!flight.usable[k]) continue;
    const double excess =
        (readings[k] - flight.omega[k]).cwiseProduct(inverse_sigma).squaredNorm() / 3.0 - 1.0;
    sum = std::max(0.0, sum + excess - kDrift);
    if (sum == 0.0) start = k + 1;
    if (sum > kAlarm) return flight.time_s[std::min(start, flight.size() - 1)];
  }
  return std::nullopt;
}

void set_median_onset(Analysis& pooled, std::vector<double> onsets) {
  if (pooled.verdict.effect == Effect::none || onsets.empty()) return;
  std::nth_element(onsets.begin(), onsets.begin() + static_cast<std::ptrdiff_t>(onsets.size() / 2),
                   onsets.end());
  pooled.where.onset_s = onsets[onsets.size() / 2];
  pooled.notes.push_back(
      "pooled where.onset_s is the median over flights, seconds after each flight's start");
}

}  // namespace aloft::host::diagnose
