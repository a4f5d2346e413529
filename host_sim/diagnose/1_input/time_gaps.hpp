// Gaps in a flight's time stamps: a step much longer than the usual one (dropped samples).
#pragma once

#include <vector>

#include "readers/time_stamps.hpp"  // the gap rule, steps_followed_by_gap

namespace aloft::host::diagnose {

struct TimeGap {
  double from_s = 0.0;
  double to_s = 0.0;
};

// The gaps by readers/time_stamps.hpp's rule, as intervals.
std::vector<TimeGap> time_gaps(const std::vector<double>& time_s);

}  // namespace aloft::host::diagnose
