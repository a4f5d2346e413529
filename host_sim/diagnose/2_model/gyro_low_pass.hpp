// The gyro's own low-pass as part of the measurement model: where a flight's gyro sits
// behind a filter (Flight::low_pass), the model's readings pass through the same causal
// filter before they are compared, instead of the rates as simulated.
//
// Why: behind a first-order filter of time constant RC the logged rate is w - RC w' +
// RC^2 w'' - ..., behind a Butterworth w - (sqrt 2 / wc) w' + (1 / wc^2) w'' - .... The
// first term is a delay, which a rigid body's fitted start takes up; the rest is not. A
// wheel a motor spins up bends the rate at its start, and at 1 kHz behind a 53 Hz PT1 the
// four flights' own axes of it then disagreed by 0.03 degrees where their noise allowed
// 0.001 (docs/validation/diagnose-accuracy.md, the spin-up sessions).
//
// The filter starts settled at the first prediction (as if the rate had held there): what
// it carried from before the window (the throw) is not known; it fades within a few RC.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/read_samples.hpp"

namespace aloft::host::diagnose {

// Whether the flight's readings are compared through its gyro's low-pass.
inline bool behind_low_pass(const Flight& flight) {
  return flight.low_pass.order > 0 && flight.low_pass.cutoff_hz > 0.0 && flight.low_pass.sample_hz > 0.0;
}

// The samples a prediction must make: every one where the filter runs over all of them.
inline ReadSamples samples_made(const Flight& flight, ReadSamples read) {
  return behind_low_pass(flight) ? ReadSamples{} : read;
}

// `readings` (one a sample of `flight`) through the flight's gyro low-pass, in place; left
// as they are when it has none.
void pass_through_low_pass(const Flight& flight, std::vector<Eigen::Vector3d>& readings);

}  // namespace aloft::host::diagnose
