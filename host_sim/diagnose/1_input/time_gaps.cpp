#include "diagnose/1_input/time_gaps.hpp"

namespace aloft::host::diagnose {

std::vector<TimeGap> time_gaps(const std::vector<double>& time_s) {
  std::vector<TimeGap> gaps;
  const std::vector<char> gap = steps_followed_by_gap(time_s);
  for (std::size_t k = 0; k + 1 < time_s.size(); ++k) {
    if (gap[k]) gaps.push_back({time_s[k], time_s[k + 1]});
  }
  return gaps;
}

}  // namespace aloft::host::diagnose
