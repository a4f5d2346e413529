// A saturated gyro reads its full-scale value for as long as the true rate exceeds it:
// flat tops. Those samples say only "at least this fast", so every fit leaves them out.
#pragma once

#include <cstddef>

#include "diagnose/1_input/flight.hpp"

namespace aloft::host::diagnose {

struct Saturation {
  std::size_t samples = 0;   // samples marked unusable
  double level_rad_s = 0.0;  // the largest flat-top level found
};

// Marks as unusable every sample in a run of >= 3 consecutive identical readings on one
// axis at >= 90 % of that axis's largest magnitude (a real rate is never that steady at
// its peak while noise is present). Returns what it marked.
Saturation mark_saturated_samples(Flight& flight);

}  // namespace aloft::host::diagnose
