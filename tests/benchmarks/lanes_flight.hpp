// One full flight (872 RK4 steps in the principal frame) for as many simulations as one
// SIMD register holds, reported per flight. Plain numbers in, no Eigen: the AVX2 unit
// (bench_lanes_avx2.cpp) includes this and must not compile inline code the baseline
// unit might share.
#pragma once

#include <benchmark/benchmark.h>

#include "aloft/dynamics/principal_dynamics.hpp"

namespace aloft_bench {

constexpr int kFlightSteps = 872;  // 0.872 s at 1 kHz: 873 samples

template <typename Lanes>
void full_flight_lanes(benchmark::State& bench, const aloft::EulerCoefficients<double>& c1,
                       const aloft::PrincipalState<double>& one) {
  constexpr int L = aloft::LaneTraits<Lanes>::count;
  const aloft::EulerCoefficients<Lanes> c{Lanes(c1.c1), Lanes(c1.c2), Lanes(c1.c3)};
  for (auto _ : bench) {
    aloft::PrincipalState<Lanes> s{{Lanes(one.q.w), Lanes(one.q.x), Lanes(one.q.y), Lanes(one.q.z)},
                                   {Lanes(one.w.x), Lanes(one.w.y), Lanes(one.w.z)}};
    for (int k = 0; k < kFlightSteps; ++k) aloft::principal_rk4_step(c, s, Lanes(1e-3));
    benchmark::DoNotOptimize(s);
  }
  bench.counters["lanes"] = L;
  bench.counters["per_flight"] = benchmark::Counter(
      static_cast<double>(bench.iterations() * L), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// bench_lanes_avx2.cpp: the same with xsimd's AVX2 register (4 doubles), and whether
// this CPU can run it.
bool avx2_fma_supported();
void full_flight_lanes_avx2(benchmark::State& bench, const aloft::EulerCoefficients<double>& c,
                            const aloft::PrincipalState<double>& one);

}  // namespace aloft_bench
