#include "readers/time_stamps.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/commands.hpp"
#include "readers/text_cells.hpp"

namespace aloft::host {

namespace {
std::string show(double t) {
  std::ostringstream out;
  out.precision(10);
  out << t;
  return out.str();
}
}  // namespace

void check_time_stamps(const std::vector<double>& time_s, const std::string& path,
                       const std::vector<std::size_t>& line_numbers) {
  for (std::size_t i = 0; i < time_s.size(); ++i) {
    const std::size_t line = i < line_numbers.size() ? line_numbers[i] : 0;
    if (!std::isfinite(time_s[i])) {
      throw Error(at_line(path, line, "time stamp is not a finite number"));
    }
    if (i == 0) continue;
    if (time_s[i] == time_s[i - 1]) {
      throw Error(at_line(path, line, "time " + show(time_s[i]) + " s repeats the previous row's"));
    }
    if (time_s[i] < time_s[i - 1]) {
      throw Error(at_line(path, line,
                          "time goes back from " + show(time_s[i - 1]) + " s to " + show(time_s[i]) + " s"));
    }
  }
}

double median_time_step(const std::vector<double>& time_s) {
  if (time_s.size() < 2) return 0.0;
  std::vector<double> steps(time_s.size() - 1);
  for (std::size_t i = 0; i + 1 < time_s.size(); ++i) steps[i] = time_s[i + 1] - time_s[i];
  const auto middle = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
  std::nth_element(steps.begin(), middle, steps.end());
  return *middle;
}

double estimated_rate_hz(const std::vector<double>& time_s) {
  const double step = median_time_step(time_s);
  return step > 0.0 ? 1.0 / step : 0.0;
}

std::vector<char> steps_followed_by_gap(const std::vector<double>& time_s) {
  std::vector<char> gap_after(time_s.size(), 0);
  const double usual = median_time_step(time_s);
  for (std::size_t k = 0; k + 1 < time_s.size(); ++k) {
    if (time_s[k + 1] - time_s[k] > kGapFactor * usual) gap_after[k] = 1;
  }
  return gap_after;
}

}  // namespace aloft::host
