// Percentiles of a sample of RMS deviation angles, for the boxplots and the tables.
// Definition: linear interpolation between order statistics at rank p (n - 1)
// (Hyndman & Fan type 7, the default of R and NumPy). Matlab's prctile, which the seed
// study used, interpolates at rank p n - 1/2 instead; on 873 or 5,000 values the two
// differ by a fraction of the gap between neighbouring values.
#pragma once

#include <vector>

namespace aloft::host {

struct DistributionSummary {
  double p10 = 0.0, p25 = 0.0, median = 0.0, p75 = 0.0, p90 = 0.0;
  double min = 0.0, max = 0.0, mean = 0.0;
};

// p in [0, 1]; `sorted` ascending and non-empty.
double percentile_of_sorted(const std::vector<double>& sorted, double p);

// Summary of `values` (copied and sorted). Throws std::invalid_argument when empty.
DistributionSummary summarise(std::vector<double> values);

}  // namespace aloft::host
