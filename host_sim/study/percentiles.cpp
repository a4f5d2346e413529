#include "study/percentiles.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace aloft::host {

double percentile_of_sorted(const std::vector<double>& sorted, double p) {
  const double rank = p * static_cast<double>(sorted.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(rank));
  const std::size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = rank - static_cast<double>(below);
  return sorted[below] + fraction * (sorted[above] - sorted[below]);
}

DistributionSummary summarise(std::vector<double> values) {
  if (values.empty()) throw std::invalid_argument("no values to summarise");
  std::sort(values.begin(), values.end());
  DistributionSummary s;
  s.p10 = percentile_of_sorted(values, 0.10);
  s.p25 = percentile_of_sorted(values, 0.25);
  s.median = percentile_of_sorted(values, 0.50);
  s.p75 = percentile_of_sorted(values, 0.75);
  s.p90 = percentile_of_sorted(values, 0.90);
  s.min = values.front();
  s.max = values.back();
  s.mean = std::accumulate(values.begin(), values.end(), 0.0) / static_cast<double>(values.size());
  return s;
}

}  // namespace aloft::host
