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
};

}  // namespace aloft::host::diagnose
