// When the gap begins (SPEC §4 `where.onset_s`).
#pragma once

#include <Eigen/Core>

#include <optional>
#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/4_judge/analysis.hpp"

namespace aloft::host::diagnose {

// One flight: the first time `readings` (a model fitted to the start of the flight) stop
// explaining the data. A one-sided CUSUM of the per-sample chi-square excess
// (|residual/sigma|^2/3 - 1, mean 0 under noise) with drift 0.5 and alarm at 15; the
// onset is the last time the sum was at zero before the alarm. Under noise alone its
// average run length is far beyond any flight. None when it never alarms.
std::optional<double> cusum_onset(const Flight& flight, const std::vector<Eigen::Vector3d>& readings,
                                  const Eigen::Vector3d& inverse_sigma);

// A session: the median of the flights' onsets, each in seconds after its flight's start,
// said in a note; nothing when the pooled verdict is none or no flight has an onset.
void set_median_onset(Analysis& pooled, std::vector<double> onsets_after_start);

}  // namespace aloft::host::diagnose
