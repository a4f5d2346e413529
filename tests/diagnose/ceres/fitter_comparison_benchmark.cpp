// The hand-written Levenberg-Marquardt (diagnose/3_fit/levenberg_marquardt.hpp) against
// Ceres on the same fits, in the same run (issue 30, item 4; docs/validation/diagnose-speed.md). Each fit
// is an effect fitted to generated flights the way fit_effect fits it
// (effect_fit_problem.hpp): four effects on one 1 s, 1 kHz flight each, and
// internal_momentum pooled over a session of 20 flights that share it. Every iteration runs both fitters from
// the same start, in turn; the counters say what each reached and what it cost:
//   hand_cost, ceres_cost   sum of squared weighted residuals at the end (chi-square)
//   ceres_minus_hand        their difference (negative: Ceres went lower)
//   theta_difference        largest difference of the fitted effect parameters
//   *_iterations            steps tried, accepted or not
//   *_sims                  predictions of one flight (residual evaluations and
//                           differenced columns): what a fit costs here
//   hand_bare_sims          the fitter's, without the Jacobian at the solution that the
//                           standard errors need (normal_at_solution false)
//   product_minus_hand      fit_effect's own cost on the same data, less the fitter's here
//   ceres_*_evals           Ceres' own counts of residual and Jacobian evaluations
//   *_ms, ceres_over_hand   CPU time of one fit, and Ceres' time over the fitter's
// Run: build/host/tests/diagnose/fitter_comparison_benchmark (the Ceres solver is in
// each benchmark's name).
#include <benchmark/benchmark.h>

#include <time.h>

#include <cmath>
#include <map>
#include <string>

#include "ceres/ceres_arrow_fit.hpp"
#include "ceres/effect_fit_problem.hpp"
#include "diagnose/1_input/flight_input.hpp"
#include "generator/flight_generator.hpp"

using namespace aloft::host;
using namespace aloft::host::diagnose;

namespace {

// `throw_seed` nonzero: the effect from `seed`, the throw and its noise from throw_seed
// (flights of one session share their effect).
aloft::generator::GeneratedFlight make(const std::string& effect, std::uint64_t seed,
                                       std::uint64_t throw_seed = 0) {
  aloft::generator::FlightSpec spec;
  spec.body = "box";
  spec.effect = effect;
  spec.duration_s = 1.0;
  spec.throw_seed = throw_seed;
  return aloft::generator::generate_flight(spec, seed);
}

// `effect` on one generated flight, fitted with `effect`.
std::unique_ptr<EffectFitProblem> one_flight(Effect effect) {
  const auto g = make(effect_name(effect), 7);
  std::vector<Flight> flights{flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, "bench")};
  return effect_fit_problem(effect, std::move(flights), NominalInertia::of(g.body.inertia));
}

// A session as rotor_cases.hpp's: one body carrying one rotor (internal_momentum, three
// parameters shared by every flight), each flight its own throw and noise.
std::unique_ptr<EffectFitProblem> session_of_20() {
  std::vector<Flight> flights;
  NominalInertia nominal;
  for (std::uint64_t i = 0; i < 20; ++i) {
    const auto g = make("internal_momentum", 100, 1000 + i);
    flights.push_back(flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, std::to_string(i)));
    nominal = NominalInertia::of(g.body.inertia);
  }
  return effect_fit_problem(Effect::internal_momentum, std::move(flights), nominal);
}

// The fits weighed, by name; a single-flight fit is named after its effect.
const std::vector<Effect> kOneFlightEffects = {Effect::inertia_moments, Effect::gyro_bias,
                                               Effect::aero_torque, Effect::internal_damping};
constexpr const char* kSession = "session_of_20";

// Each fit made once per run, outside the timed region, whatever solver weighs it.
const EffectFitProblem& fit_named(const std::string& name) {
  static std::map<std::string, std::unique_ptr<EffectFitProblem>> made;
  std::unique_ptr<EffectFitProblem>& fit = made[name];
  if (fit) return *fit;
  if (name == kSession) {
    fit = session_of_20();
  } else {
    for (Effect effect : kOneFlightEffects) {
      if (name == effect_name(effect)) fit = one_flight(effect);
    }
  }
  return *fit;
}

// CPU time of this thread: the fits run on one, and the machine is shared, so wall time
// would count other processes' turns.
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

void weigh(benchmark::State& state, const std::string& name, ceres::LinearSolverType solver) {
  const EffectFitProblem& fit = fit_named(name);
  CeresArrowOptions options;
  options.linear_solver = solver;
  LeastSquaresResult hand;
  CeresArrowResult ceres_fit;
  double hand_s = 0.0, ceres_s = 0.0;
  long hand_sims = 0, ceres_sims = 0;
  int rounds = 0;
  for (auto _ : state) {
    fit.simulations = 0;
    double start = thread_seconds();
    hand = minimise(fit.problem, fit.theta_start, fit.rates_start);
    hand_s += thread_seconds() - start;
    hand_sims = fit.simulations;
    fit.simulations = 0;
    start = thread_seconds();
    ceres_fit = minimise_with_ceres(fit.problem, fit.theta_start, fit.rates_start, options);
    ceres_s += thread_seconds() - start;
    // Less the one evaluation a block that sizes Ceres' residual blocks (the count is
    // known without it: three a sample).
    ceres_sims = fit.simulations - fit.problem.block_count;
    ++rounds;
  }
  // The fitter as a caller that wants no standard errors runs it (no Jacobian at the
  // solution, which Ceres does not make either): counted once, untimed.
  LeastSquaresOptions bare;
  bare.normal_at_solution = false;
  fit.simulations = 0;
  const double bare_cost = minimise(fit.problem, fit.theta_start, fit.rates_start, bare).cost;
  state.counters["hand_bare_sims"] = static_cast<double>(fit.simulations.load());
  state.counters["hand_bare_cost_change"] = bare_cost - hand.cost;
  // The product's own fit of the same data (fit_effect: the sensor's columns read off the
  // prediction, internal damping's start searched on its grid), to show the rebuilt
  // problem is the one it solves.
  const EffectFit product = fit_effect(fit.model.effect, fit.model.nominal, fit.data, &fit.nominal_fit);
  state.counters["product_minus_hand"] = product.cost - hand.cost;
  state.counters["ceres_residual_evals"] = ceres_fit.residual_evaluations;
  state.counters["ceres_jacobian_evals"] = ceres_fit.jacobian_evaluations;
  state.counters["hand_cost"] = hand.cost;
  state.counters["ceres_cost"] = ceres_fit.cost;
  state.counters["ceres_minus_hand"] = ceres_fit.cost - hand.cost;
  state.counters["theta_difference"] = (ceres_fit.shared - hand.shared).cwiseAbs().maxCoeff();
  state.counters["hand_iterations"] = hand.iterations;
  state.counters["ceres_iterations"] = ceres_fit.iterations;
  state.counters["ceres_converged"] = ceres_fit.converged ? 1 : 0;
  state.counters["hand_sims"] = static_cast<double>(hand_sims);
  state.counters["ceres_sims"] = static_cast<double>(ceres_sims);
  state.counters["hand_ms"] = 1e3 * hand_s / rounds;
  state.counters["ceres_ms"] = 1e3 * ceres_s / rounds;
  state.counters["ceres_over_hand"] = ceres_s / hand_s;
}

void register_all() {
  const std::vector<std::pair<const char*, ceres::LinearSolverType>> solvers = {
      {"DENSE_QR", ceres::DENSE_QR},
      {"DENSE_NORMAL_CHOLESKY", ceres::DENSE_NORMAL_CHOLESKY},
      {"DENSE_SCHUR", ceres::DENSE_SCHUR}};
  std::vector<std::string> names;
  for (Effect effect : kOneFlightEffects) names.emplace_back(effect_name(effect));
  names.emplace_back(kSession);
  for (const std::string& name : names) {
    for (const auto& [solver_name, solver] : solvers) {
      benchmark::RegisterBenchmark(
          (name + "/" + solver_name).c_str(),
          [name, solver = solver](benchmark::State& state) { weigh(state, name, solver); })
          ->Unit(benchmark::kMillisecond)
          ->Iterations(name == kSession ? 3 : 50);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
