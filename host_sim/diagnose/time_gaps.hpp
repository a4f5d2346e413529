// Gaps in a flight's time stamps: a step much longer than the usual one (dropped samples).
#pragma once

#include <vector>

namespace aloft::host::diagnose {

struct TimeGap {
  double from_s = 0.0;
  double to_s = 0.0;
};

// A step longer than 1.5 x the median step is a gap: jitter of a phone's sampling
// stays well inside that, one dropped sample already doubles the step.
constexpr double kGapFactor = 1.5;

// gap[k] != 0 when the step from sample k to k+1 is a gap (size n; the last entry is 0).
std::vector<char> steps_followed_by_gap(const std::vector<double>& time_s);

std::vector<TimeGap> time_gaps(const std::vector<double>& time_s);

}  // namespace aloft::host::diagnose
