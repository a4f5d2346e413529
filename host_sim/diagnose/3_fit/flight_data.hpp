// One flight as a fit sees it: the samples it may use and the noise that weighs their
// residuals. What every fit of this stage takes (effect_fit.hpp, initial_state_fit.hpp).
#pragma once

#include <Eigen/Core>

#include <vector>

#include "diagnose/1_input/flight.hpp"

namespace aloft::host::diagnose {

// Samples a fit may use (1) or must not see (0); one entry per sample of the flight.
using SampleMask = std::vector<char>;

struct FlightData {
  const Flight* flight = nullptr;
  SampleMask mask;                // training samples of this fit
  Eigen::Vector3d inverse_sigma;  // 1 / noise floor per axis

  // Sample k is compared: the fit trains on it and the reading is a measurement.
  bool compared(std::size_t k) const { return mask[k] != 0 && flight->usable[k]; }
  // Residuals the fit compares: three a compared sample.
  int residual_count() const {
    int count = 0;
    for (std::size_t k = 0; k < mask.size(); ++k) count += compared(k) ? 3 : 0;
    return count;
  }
};

}  // namespace aloft::host::diagnose
