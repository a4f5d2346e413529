// Checks and summaries of a trial's time stamps, shared by every reader.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace aloft::host {

// Throws aloft::host::Error "PATH:LINE: ..." at the first time stamp that is not finite,
// repeats the one before it, or goes back in time. line_numbers[i] is the file line of
// time_s[i] (same size).
void check_time_stamps(const std::vector<double>& time_s, const std::string& path,
                       const std::vector<std::size_t>& line_numbers);

// The median of the steps between consecutive time stamps (0 with fewer than two). The
// median, not the mean, so that a few gaps or jittery samples do not bias the rate.
double median_time_step(const std::vector<double>& time_s);

// 1 / median_time_step, or 0 when it cannot be told.
double estimated_rate_hz(const std::vector<double>& time_s);

// The one rule of every command for lost samples: a step longer than kGapFactor times the
// median step is a gap. Jitter of a phone's sampling stays well inside it; one dropped
// sample already doubles the step.
constexpr double kGapFactor = 1.5;

// gap_after[k] != 0 when the step from sample k to k + 1 is a gap (size n, the last 0).
std::vector<char> steps_followed_by_gap(const std::vector<double>& time_s);

}  // namespace aloft::host
