// Compiled with -mavx512f -mavx512dq -mavx2 -mfma when the compiler targets x86-64
// (host_sim/study/CMakeLists.txt); see full_flight_wide_lanes.hpp.
#include "study/full_flight_wide_lanes.hpp"

#if defined(__AVX512F__) && defined(__AVX512DQ__)
#include "aloft/lanes/xsimd_lanes.hpp"

namespace aloft::host {

bool full_flight_lanes_avx512_supported() {
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
}

void run_full_flight_lanes_avx512(const FlightArrays<double>& flight, const FlightSimulation<double>* sims,
                                  SquaredDeviations<double>* out) {
  using Lanes = xsimd::batch<double, xsimd::avx512f>;
  static_assert(LaneTraits<Lanes>::count == kFullFlightLanesAvx512, "8 doubles per AVX-512 register");
  BatchFlight<Lanes>::run(flight, sims, out);
}

}  // namespace aloft::host
#else
namespace aloft::host {

bool full_flight_lanes_avx512_supported() { return false; }
void run_full_flight_lanes_avx512(const FlightArrays<double>&, const FlightSimulation<double>*,
                                  SquaredDeviations<double>*) {}

}  // namespace aloft::host
#endif
