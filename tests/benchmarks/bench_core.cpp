// The core's speed: one RK4 step (double, float), one splitting step, one onboard-check
// update with K = 8 live simulations, and a whole 0.872 s flight at 1 kHz done by aloft's
// RK4 and by Boost.Odeint's runge_kutta4 on the same equations (same state, same step,
// same renormalisation), so the ratio of the two is measured in one run.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdlib>
#include <boost/numeric/odeint.hpp>

#include "aloft/aloft.hpp"
#include "aloft/lanes/xsimd_lanes.hpp"
#include "lanes_flight.hpp"

namespace {

template <typename S>
aloft::InertiaTensor<S> gf_cylinder_tilted() {
  // The study's cylinder with its principal axes a little off the body axes (full tensor).
  aloft::InertiaTensor<S> inertia;
  const aloft::Status made = aloft::InertiaTensor<S>::make_from_principal(
      aloft::Vec3<S>(S(0.0183892), S(0.0183892), S(0.0210806)),
      aloft::quat_wxyz(S(0.999), S(0.03), S(-0.02), S(0.01)).normalized(), inertia);
  if (made != aloft::Status::ok) std::abort();
  return inertia;
}

template <typename S>
aloft::RigidBodyState<S> thrown_state() {
  aloft::RigidBodyState<S> state;
  state.omega_body = aloft::Vec3<S>(S(4), S(-6), S(11));
  return state;
}

// One step of a core integrator (RK4 or splitting) in scalar type S.
template <template <typename> class Integrator, typename S>
void BM_Step(benchmark::State& bench) {
  const Integrator<S> integrator(gf_cylinder_tilted<S>());
  aloft::RigidBodyState<S> state = thrown_state<S>();
  for (auto _ : bench) {
    benchmark::DoNotOptimize(integrator.step(state, S(1e-3)));
    benchmark::DoNotOptimize(state);
  }
}
template <typename S>
using SplittingIntegrator = aloft::SplittingIntegrator<S>;  // default order: fourth
BENCHMARK_TEMPLATE(BM_Step, aloft::Rk4Integrator, double)->Name("BM_Rk4Step<double>");
BENCHMARK_TEMPLATE(BM_Step, aloft::Rk4Integrator, float)->Name("BM_Rk4Step<float>");
BENCHMARK_TEMPLATE(BM_Step, SplittingIntegrator, double)->Name("BM_SplittingStep<double>");
BENCHMARK_TEMPLATE(BM_Step, SplittingIntegrator, float)->Name("BM_SplittingStep<float>");

template <typename S>
void BM_OnboardCheckUpdateK8(benchmark::State& bench) {
  // A recorded second of gyro samples, replayed; seeds every 10 samples so 8 live
  // simulations are always stepping after the first 80 samples.
  const aloft::InertiaTensor<S> inertia = gf_cylinder_tilted<S>();
  const aloft::Rk4Integrator<S> integrator(inertia);
  std::array<aloft::Vec3<S>, 1000> gyro;
  aloft::RigidBodyState<S> state = thrown_state<S>();
  for (auto& g : gyro) {
    if (integrator.step(state, S(1e-3)) != aloft::Status::ok) std::abort();
    g = state.omega_body;
  }
  aloft::OnboardCheckSettings<S> settings;
  settings.seed_every = 10;
  aloft::OnboardCheck<S, 8> check(inertia, settings);
  for (int k = 0; k < 100; ++k) {
    if (check.update(gyro[std::size_t(k)], S(1e-3)) != aloft::Status::ok) std::abort();
  }
  std::size_t k = 0;
  for (auto _ : bench) {
    benchmark::DoNotOptimize(check.update(gyro[k], S(1e-3)));
    k = (k + 1) % gyro.size();
    benchmark::DoNotOptimize(check);
  }
  bench.counters["live"] = check.live_simulations();
}
BENCHMARK_TEMPLATE(BM_OnboardCheckUpdateK8, double);
BENCHMARK_TEMPLATE(BM_OnboardCheckUpdateK8, float);

using aloft_bench::kFlightSteps;

// aloft as a hot loop uses it: into the principal frame once, 872 steps there, and
// back into body axes at the end (where Odeint also ends with its state).
void BM_FullFlight_aloft(benchmark::State& bench) {
  const aloft::Rk4Integrator<double> integrator(gf_cylinder_tilted<double>());
  for (auto _ : bench) {
    aloft::PrincipalState<double> s = integrator.frame().to_principal(thrown_state<double>());
    for (int k = 0; k < kFlightSteps; ++k) integrator.step_principal(s, 1e-3);
    aloft::RigidBodyState<double> state = integrator.frame().to_body(s);
    benchmark::DoNotOptimize(state);
  }
}
BENCHMARK(BM_FullFlight_aloft);

// The same flight for as many simulations as one SIMD register holds, each its own
// tensor: time per flight (lanes_flight.hpp). This build's register (xsimd::batch<double>:
// SSE2, 2 doubles), and AVX2 with FMA (4 doubles) where the CPU has them.
void BM_FullFlight_aloft_lanes(benchmark::State& bench) {
  const aloft::Rk4Integrator<double> integrator(gf_cylinder_tilted<double>());
  aloft_bench::full_flight_lanes<xsimd::batch<double>>(
      bench, integrator.frame().coefficients(), integrator.frame().to_principal(thrown_state<double>()));
}
void BM_FullFlight_aloft_lanes_avx2(benchmark::State& bench) {
  if (!aloft_bench::avx2_fma_supported()) {
    bench.SkipWithError("this CPU has no AVX2 and FMA");
    return;
  }
  const aloft::Rk4Integrator<double> integrator(gf_cylinder_tilted<double>());
  aloft_bench::full_flight_lanes_avx2(bench, integrator.frame().coefficients(),
                                      integrator.frame().to_principal(thrown_state<double>()));
}
BENCHMARK(BM_FullFlight_aloft_lanes_avx2);
BENCHMARK(BM_FullFlight_aloft_lanes);

// The same flight through the body-state API, Rk4Integrator::step_unchecked, which
// crosses the principal frame at every step.
void BM_FullFlight_aloft_body_steps(benchmark::State& bench) {
  const aloft::Rk4Integrator<double> integrator(gf_cylinder_tilted<double>());
  for (auto _ : bench) {
    aloft::RigidBodyState<double> state = thrown_state<double>();
    for (int k = 0; k < kFlightSteps; ++k) integrator.step_unchecked(state, 1e-3);
    benchmark::DoNotOptimize(state);
  }
}
BENCHMARK(BM_FullFlight_aloft_body_steps);

// The same system for Odeint: x = (qw, qx, qy, qz, wx, wy, wz).
using OdeState = std::array<double, 7>;
struct TorqueFreeSystem {
  Eigen::Matrix3d tensor;
  Eigen::Matrix3d inverse;
  void operator()(const OdeState& x, OdeState& dxdt, double /*t*/) const {
    const Eigen::Vector3d w(x[4], x[5], x[6]);
    const Eigen::Vector3d dw = inverse * (tensor * w).cross(w);
    dxdt[0] = 0.5 * (-x[1] * w.x() - x[2] * w.y() - x[3] * w.z());
    dxdt[1] = 0.5 * (x[0] * w.x() + x[2] * w.z() - x[3] * w.y());
    dxdt[2] = 0.5 * (x[0] * w.y() + x[3] * w.x() - x[1] * w.z());
    dxdt[3] = 0.5 * (x[0] * w.z() + x[1] * w.y() - x[2] * w.x());
    dxdt[4] = dw.x();
    dxdt[5] = dw.y();
    dxdt[6] = dw.z();
  }
};

void BM_FullFlight_odeint(benchmark::State& bench) {
  const aloft::InertiaTensor<double> inertia = gf_cylinder_tilted<double>();
  const TorqueFreeSystem system{inertia.tensor(), inertia.inverse()};
  boost::numeric::odeint::runge_kutta4<OdeState> stepper;
  for (auto _ : bench) {
    const aloft::RigidBodyState<double> start = thrown_state<double>();
    OdeState x = {1.0, 0.0, 0.0, 0.0, start.omega_body.x(), start.omega_body.y(), start.omega_body.z()};
    for (int k = 0; k < kFlightSteps; ++k) {
      stepper.do_step(system, x, 0.0, 1e-3);
      const double n = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
      for (int i = 0; i < 4; ++i) x[std::size_t(i)] /= n;
    }
    benchmark::DoNotOptimize(x);
  }
}
BENCHMARK(BM_FullFlight_odeint);

}  // namespace

BENCHMARK_MAIN();
