// A session's flip-period figure: the mean relative error of the predicted periods
// (flip_period.hpp) over the flights that flip about the intermediate axis, as the
// racquet study reports it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "diagnose/4_judge/flip_period.hpp"

namespace aloft::host::diagnose {

// Mean relative flip-period error over the flights of a session that flip about the
// intermediate axis (segment comment says "intermediate"; all flights with a period if
// none says so).
struct FlipPeriodSummary {
  int flights = 0;
  // From the first sample (flip_period.hpp).
  double mean_error_nominal = 0.0;
  double mean_error_diagnosed = 0.0;  // over the same flights
  int diagnosed_flights = 0;
  // From each flight's fitted initial state, over the flights with both predictions.
  double mean_error_nominal_fitted = 0.0;
  double mean_error_diagnosed_fitted = 0.0;
  int fitted_flights = 0;
};

// `periods[i]` of the flight whose segment comment is `comments[i]`; none when no flight
// counts.
std::optional<FlipPeriodSummary> summarize_flip_periods(
    const std::vector<std::string>& comments, const std::vector<std::optional<FlipPeriod>>& periods);

}  // namespace aloft::host::diagnose
