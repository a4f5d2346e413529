// The batch integrator compiled for AVX2 and FMA (4 doubles per register), in a
// translation unit of its own built with -mavx2 -mfma, chosen at run time only on a CPU
// that has both; anywhere else the baseline SSE2 build runs (study/full_flight_simulation).
// The unit takes and returns plain arrays only, so no inline function compiled for AVX2
// can be picked by the linker for code that runs on an older CPU.
#pragma once

#include <cstddef>

#include "aloft/batch_flight.hpp"

namespace aloft::host {

constexpr std::size_t kFullFlightLanesAvx2 = 4;

// Whether this CPU runs AVX2 and FMA, and the build has the AVX2 unit.
bool full_flight_lanes_avx2_supported();

// BatchFlight over 4 lanes: sims[0..4) and out[0..4).
void run_full_flight_lanes_avx2(const FlightArrays<double>& flight,
                                const FlightSimulation<double>* sims,
                                SquaredDeviations<double>* out);

}  // namespace aloft::host
