// Compiled with -mavx2 -mfma when the compiler targets x86-64 (host_sim/study/CMakeLists.txt);
// see full_flight_wide_lanes.hpp.
#include "study/full_flight_wide_lanes.hpp"

#if defined(__AVX2__) && defined(__FMA__)
#include "aloft/lanes/xsimd_lanes.hpp"

namespace aloft::host {

bool full_flight_lanes_avx2_supported() {
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

void run_full_flight_lanes_avx2(const FlightArrays<double>& flight, const FlightSimulation<double>* sims,
                                SquaredDeviations<double>* out) {
  using Lanes = xsimd::batch<double, xsimd::avx2>;
  static_assert(LaneTraits<Lanes>::count == kFullFlightLanesAvx2, "4 doubles per AVX2 register");
  BatchFlight<Lanes>::run(flight, sims, out);
}

}  // namespace aloft::host
#else
namespace aloft::host {

bool full_flight_lanes_avx2_supported() { return false; }
void run_full_flight_lanes_avx2(const FlightArrays<double>&, const FlightSimulation<double>*,
                                SquaredDeviations<double>*) {}

}  // namespace aloft::host
#endif
