#include "diagnose/4_judge/flip_period_summary.hpp"

#include <algorithm>
#include <cctype>

namespace aloft::host::diagnose {
namespace {

bool mentions_intermediate(const std::string& comment) {
  std::string lower = comment;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower.find("intermediate") != std::string::npos;
}

}  // namespace

std::optional<FlipPeriodSummary> summarize_flip_periods(
    const std::vector<std::string>& comments, const std::vector<std::optional<FlipPeriod>>& periods) {
  bool any_intermediate = false;
  for (const std::string& c : comments) any_intermediate = any_intermediate || mentions_intermediate(c);
  FlipPeriodSummary summary;
  for (std::size_t i = 0; i < periods.size(); ++i) {
    const auto& fp = periods[i];
    if (!fp || (any_intermediate && !mentions_intermediate(comments[i]))) continue;
    ++summary.flights;
    summary.mean_error_nominal += fp->nominal_error();
    if (fp->diagnosed_s) {
      ++summary.diagnosed_flights;
      summary.mean_error_diagnosed += fp->error(*fp->diagnosed_s);
    }
    if (fp->nominal_fitted_s && fp->diagnosed_fitted_s) {
      ++summary.fitted_flights;
      summary.mean_error_nominal_fitted += fp->error(*fp->nominal_fitted_s);
      summary.mean_error_diagnosed_fitted += fp->error(*fp->diagnosed_fitted_s);
    }
  }
  if (summary.flights == 0) return std::nullopt;
  summary.mean_error_nominal /= summary.flights;
  if (summary.diagnosed_flights > 0) summary.mean_error_diagnosed /= summary.diagnosed_flights;
  if (summary.fitted_flights > 0) {
    summary.mean_error_nominal_fitted /= summary.fitted_flights;
    summary.mean_error_diagnosed_fitted /= summary.fitted_flights;
  }
  return summary;
}

}  // namespace aloft::host::diagnose
