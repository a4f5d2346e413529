#include "diagnose/time_gaps.hpp"

#include <algorithm>

namespace aloft::host::diagnose {
namespace {

double median_step(const std::vector<double>& t) {
  if (t.size() < 2) return 0.0;
  std::vector<double> steps;
  for (std::size_t k = 1; k < t.size(); ++k) steps.push_back(t[k] - t[k - 1]);
  const auto mid = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
  std::nth_element(steps.begin(), mid, steps.end());
  return *mid;
}

}  // namespace

std::vector<char> steps_followed_by_gap(const std::vector<double>& time_s) {
  std::vector<char> gap(time_s.size(), 0);
  const double usual = median_step(time_s);
  for (std::size_t k = 0; k + 1 < time_s.size(); ++k) {
    if (time_s[k + 1] - time_s[k] > kGapFactor * usual) gap[k] = 1;
  }
  return gap;
}

std::vector<TimeGap> time_gaps(const std::vector<double>& time_s) {
  std::vector<TimeGap> gaps;
  const std::vector<char> gap = steps_followed_by_gap(time_s);
  for (std::size_t k = 0; k + 1 < time_s.size(); ++k) {
    if (gap[k]) gaps.push_back({time_s[k], time_s[k + 1]});
  }
  return gaps;
}

}  // namespace aloft::host::diagnose
