// The batch integrator compiled for wider registers than the x86-64 baseline (SSE2,
// 2 doubles): AVX2 with FMA (4 doubles) and AVX-512 (8 doubles), each in a translation
// unit of its own built with those instructions (host_sim/study/CMakeLists.txt) and
// chosen at run time only on a CPU that has them; anywhere else the baseline build runs
// (study/full_flight_simulation.cpp). The units take and return plain arrays only, so
// no inline function compiled for a wider instruction set can be picked by the linker
// for code that runs on an older CPU.
#pragma once

#include <cstddef>

#include "aloft/lanes/batch_flight.hpp"

namespace aloft::host {

constexpr std::size_t kFullFlightLanesAvx2 = 4;
constexpr std::size_t kFullFlightLanesAvx512 = 8;

// Whether this CPU runs each, and the build has its unit.
bool full_flight_lanes_avx2_supported();
bool full_flight_lanes_avx512_supported();

// BatchFlight over 4 (AVX2) or 8 (AVX-512) lanes: sims[0..lanes) and out[0..lanes).
void run_full_flight_lanes_avx2(const FlightArrays<double>& flight, const FlightSimulation<double>* sims,
                                SquaredDeviations<double>* out);
void run_full_flight_lanes_avx512(const FlightArrays<double>& flight, const FlightSimulation<double>* sims,
                                  SquaredDeviations<double>* out);

}  // namespace aloft::host
