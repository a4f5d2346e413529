// Which samples of a prediction its caller reads (flight_model.hpp).
#pragma once

#include <cstddef>

namespace aloft::host::diagnose {

// The samples whose readings a caller reads: those whose flag is set in both arrays (a
// fit's training mask and the flight's usable flags, one entry a sample). A prediction
// leaves the others between its steps at zero instead of interpolating them (a fold fit
// compares half the samples: case00 380.7 -> 377.0 M instructions); the steps, and so every
// reading it does make, are the same. Null: every sample.
struct ReadSamples {
  const char* mask = nullptr;
  const char* usable = nullptr;
  bool wanted(std::size_t k) const { return mask == nullptr || (mask[k] != 0 && usable[k] != 0); }
};

}  // namespace aloft::host::diagnose
