// Compiled with -mavx2 -mfma (CMakeLists.txt); see lanes_flight.hpp.
#include "lanes_flight.hpp"

#if defined(__AVX2__) && defined(__FMA__)
#include "aloft/lanes/xsimd_lanes.hpp"

namespace aloft_bench {
bool avx2_fma_supported() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }
void full_flight_lanes_avx2(benchmark::State& bench, const aloft::EulerCoefficients<double>& c,
                            const aloft::PrincipalState<double>& one) {
  full_flight_lanes<xsimd::batch<double, xsimd::avx2>>(bench, c, one);
}
}  // namespace aloft_bench
#else
namespace aloft_bench {
bool avx2_fma_supported() { return false; }
void full_flight_lanes_avx2(benchmark::State&, const aloft::EulerCoefficients<double>&,
                            const aloft::PrincipalState<double>&) {}
}  // namespace aloft_bench
#endif
