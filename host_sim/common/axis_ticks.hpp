// Round tick marks for a figure's axis: steps of 1, 2 or 5 times a power of ten, so a
// reader sees 0, 5, 10, 15 rather than 0, 4.37, 8.74. Shared by every figure aloft draws.
#pragma once

#include <string>
#include <vector>

namespace aloft::host {

struct AxisTicks {
  std::vector<double> values;  // from the first tick at or below lo to the last at or above hi
  double step = 1.0;
  int decimals = 0;  // enough to tell neighbouring ticks apart, no more
  double first() const { return values.front(); }
  double last() const { return values.back(); }
};

// About `count` intervals (never fewer than count / 2, never more than 2 count) covering
// [lo, hi]; the axis should run from first() to last(). lo == hi gets a unit-wide axis.
AxisTicks round_ticks(double lo, double hi, int count = 5);

// Round ticks that lie within [lo, hi], for an axis that runs exactly from lo to hi: a
// time axis that ends where the flight ends (round_ticks would run a 0.81 s flight's
// axis to 1 s).
AxisTicks ticks_within(double lo, double hi, int count = 5);

// A tick value at the ticks' precision: "0", "0.25", "-1.5" (never "-0").
std::string tick_label(double value, int decimals);

}  // namespace aloft::host
