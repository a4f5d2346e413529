// Figure axes: round ticks, and a time axis that ends where the flight ends (issue 26
// item 5: the per-flight plot's time axis always ran to 1 s).
#include <catch2/catch.hpp>

#include "common/axis_ticks.hpp"

using aloft::host::round_ticks;
using aloft::host::ticks_within;

TEST_CASE("round ticks cover the range in steps of 1, 2 or 5", "[axis_ticks]") {
  const auto t = round_ticks(0.0, 0.81, 8);
  CHECK(t.step == Approx(0.2));
  CHECK(t.last() == Approx(1.0));  // round_ticks runs on to a round end
}

TEST_CASE("a flight's time axis holds only ticks within the flight", "[axis_ticks]") {
  for (double end : {0.45, 0.81, 0.95, 1.0, 1.23, 2.7}) {
    CAPTURE(end);
    const auto t = ticks_within(0.0, end, 8);
    CHECK(t.first() == Approx(0.0));
    CHECK(t.last() <= end + 1e-12);
    CHECK(t.last() > end - t.step);
    CHECK(t.values.size() >= 3);
  }
}
