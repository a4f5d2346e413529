#include "common/axis_ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aloft::host {

AxisTicks round_ticks(double lo, double hi, int count) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0.0, hi = 1.0;
  if (hi < lo) std::swap(lo, hi);
  if (hi == lo) hi = lo + 1.0;
  count = std::max(count, 1);
  // The smallest 1-2-5 step that covers the range in at most `count` intervals.
  const double rough = (hi - lo) / count;
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  double step = 10.0 * power;
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * power >= rough * (1.0 - 1e-12)) {
      step = m * power;
      break;
    }
  }
  AxisTicks ticks;
  ticks.step = step;
  ticks.decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  const double first = std::floor(lo / step + 1e-9);
  const double last = std::ceil(hi / step - 1e-9);
  for (double i = first; i <= last + 0.5; i += 1.0) ticks.values.push_back(i * step);
  return ticks;
}

AxisTicks ticks_within(double lo, double hi, int count) {
  AxisTicks ticks = round_ticks(lo, hi, count);
  const double slack = 1e-9 * ticks.step;
  std::vector<double> inside;
  for (double v : ticks.values) {
    if (v >= lo - slack && v <= hi + slack) inside.push_back(v);
  }
  if (!inside.empty()) ticks.values = inside;
  return ticks;
}

std::string tick_label(double value, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  std::string s(text);
  if (s.find_first_not_of("-0.") == std::string::npos && s[0] == '-') s.erase(0, 1);
  return s;
}

}  // namespace aloft::host
