// Speed of `aloft diagnose` (issues 5 and 8): one flight of 1 s at 1 kHz with every
// candidate fitted and cross-validated and the stepwise compound search (target <= 2 s),
// and a session of 60 such flights, each with its own search, then the pooled
// leave-one-flight-out analysis, on 2 threads (target <= 30 s wall). Flights come from the
// withheld-effect generator; generating them is outside the timed region. The session's
// "CPU" column is the calling thread's only; time the whole process (/usr/bin/time) for
// the CPU of both threads. A 10-minute log of 200 throws, end to end through the command
// line with its peak memory: long_log_benchmark.sh.
#include <benchmark/benchmark.h>

#include <cmath>

#include "diagnose/5_flow/diagnosis.hpp"
#include "diagnose/1_input/flight_input.hpp"
#include "generator/flight_generator.hpp"

using namespace aloft::host;
using namespace aloft::host::diagnose;

namespace {

aloft::generator::GeneratedFlight make(const char* effect, std::uint64_t seed) {
  aloft::generator::FlightSpec spec;
  spec.body = "box";
  spec.effect = effect;
  spec.duration_s = 1.0;
  return aloft::generator::generate_flight(spec, seed);
}

void one_flight(benchmark::State& state) {
  const auto g = make("gyro_bias", 7);
  const Flight flight = flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, "bench");
  const NominalInertia nominal = NominalInertia::of(g.body.inertia);
  for (auto _ : state) {
    FlightDiagnosis d = diagnose_flight(flight, nominal);
    benchmark::DoNotOptimize(d.analysis.verdict.effect);
  }
}
BENCHMARK(one_flight)->Unit(benchmark::kMillisecond)->UseRealTime();

void session_of_60(benchmark::State& state) {
  // One body and one sensor for the whole session, as in a real one: the aero torque of
  // the same throwing style, each flight its own throw and noise.
  std::vector<Flight> flights;
  const auto first = make("aero_torque", 100);
  for (std::uint64_t i = 0; i < 60; ++i) {
    const auto g = make("aero_torque", 100 + i);
    flights.push_back(flight_from_imu(g.imu, first.body, -INFINITY, INFINITY, std::to_string(i)));
  }
  const NominalInertia nominal = NominalInertia::of(first.body.inertia);
  for (auto _ : state) {
    SessionDiagnosis d = diagnose_session(flights, nominal, 2);
    benchmark::DoNotOptimize(d.pooled.verdict.effect);
  }
}
BENCHMARK(session_of_60)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
