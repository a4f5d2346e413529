// Speed of `aloft diagnose` (issues 5 and 8): one flight of 1 s at 1 kHz with every
// candidate fitted and cross-validated and the stepwise compound search (target <= 2 s),
// and a session of 60 such flights, each with its own search, then the pooled
// leave-one-flight-out analysis, on 2 threads (target <= 30 s wall). Flights come from the
// withheld-effect generator; generating them is outside the timed region. The session's
// "CPU" column is the calling thread's only; time the whole process (/usr/bin/time) for
// the CPU of both threads. A 10-minute log of 200 throws, end to end through the command
// line with its peak memory: long_log_benchmark.sh. The forward model alone, the way the
// fits step it against the way it was stepped before (issue 30), side by side in one run:
// predict_one_flight.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>

#include "diagnose/5_flow/diagnosis.hpp"
#include "diagnose/1_input/flight_input.hpp"
#include "diagnose/2_model/flight_model.hpp"
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
  Flight flight = flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, "bench");
  const NominalInertia nominal = NominalInertia::of(g.body.inertia);
  for (auto _ : state) {
    FlightDiagnosis d = diagnose_flight(flight, nominal);
    benchmark::DoNotOptimize(d.analysis.verdict.effect);
  }
}
BENCHMARK(one_flight)->Unit(benchmark::kMillisecond)->UseRealTime();

// One prediction of a 1 s, 1 kHz flight (what each residual evaluation and each
// finite-difference column of every fit costs), with the steps shared by samples (the
// fits' model) and, as the peer, one step a sample (the model before issue 30), timed in
// turn in the same iterations. Counter per_sample_over_shared: how many times longer the
// peer takes; shared_us, per_sample_us: each one's time per prediction.
void predict_one_flight(benchmark::State& state) {
  const auto g = make("inertia_axes", 7);
  Flight flight = flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, "bench");
  const EffectModel model(Effect::none, NominalInertia::of(g.body.inertia));
  const std::size_t ref = flight.size() / 2;
  const Eigen::Vector3d omega = body_rate_of_reading(flight, flight.omega[ref]);
  std::vector<Eigen::Vector3d> readings;
  constexpr int kRepeats = 50;
  const auto seconds_of = [&](SampleStepping stepping) {
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < kRepeats; ++i) {
      predict_readings(model, flight, ref, omega, Eigen::VectorXd(), readings, stepping);
      benchmark::DoNotOptimize(readings.data());
    }
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  double shared = 0.0, per_sample = 0.0;
  int rounds = 0;
  for (auto _ : state) {
    shared += seconds_of(SampleStepping::shared_steps);
    per_sample += seconds_of(SampleStepping::step_per_sample);
    ++rounds;
  }
  state.counters["per_sample_over_shared"] = per_sample / shared;
  state.counters["shared_us"] = 1e6 * shared / (rounds * kRepeats);
  state.counters["per_sample_us"] = 1e6 * per_sample / (rounds * kRepeats);
}
BENCHMARK(predict_one_flight)->Unit(benchmark::kMillisecond)->UseRealTime();

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
