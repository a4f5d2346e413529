// The study's simulations, aloft's RK4 against the same work done with Boost.Odeint's
// runge_kutta4: the GF model analysis of the built-in throw (873 full-flight
// simulations, each 872 steps with omega from consecutive orientations and the DA; the
// same loop around both steppers, so the ratio is that of the integrators).
// Report the ratio of the two times. Run: build-*/tests/study/study_benchmark
#include <benchmark/benchmark.h>

#include <boost/numeric/odeint.hpp>

#include <array>
#include <cmath>

#include "aloft/dynamics/deviation.hpp"
#include "study/built_in_study.hpp"
#include "study/full_flight_simulation.hpp"

using namespace aloft::host;

namespace {

const BuiltInTrial& trial() {
  static const BuiltInTrial t = make_built_in_trial();
  return t;
}

void BM_GfAnalysis_AloftRk4(benchmark::State& state) {
  const BuiltInTrial& t = trial();
  for (auto _ : state) {
    double sum = 0.0;
    for (std::size_t k = 0; k < t.flight.samples(); ++k) {
      sum += full_flight_rms_da_deg(t.flight, t.body.inertia, k)[frame_index(DaFrame::body)];
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(t.flight.samples()));
  state.SetLabel("items = full-flight simulations");
}

// The torque-free body for odeint: x = (qw, qx, qy, qz, wx, wy, wz).
using OdeState = std::array<double, 7>;
struct TorqueFreeBody {
  Eigen::Matrix3d inertia, inverse;
  void operator()(const OdeState& x, OdeState& dxdt, double /*t*/) const {
    const Eigen::Vector3d w(x[4], x[5], x[6]);
    const double qw = x[0], qx = x[1], qy = x[2], qz = x[3];
    dxdt[0] = 0.5 * (-qx * w.x() - qy * w.y() - qz * w.z());
    dxdt[1] = 0.5 * (qw * w.x() + qy * w.z() - qz * w.y());
    dxdt[2] = 0.5 * (qw * w.y() + qz * w.x() - qx * w.z());
    dxdt[3] = 0.5 * (qw * w.z() + qx * w.y() - qy * w.x());
    const Eigen::Vector3d a = inverse * (inertia * w).cross(w);
    dxdt[4] = a.x();
    dxdt[5] = a.y();
    dxdt[6] = a.z();
  }
};

Eigen::Quaterniond orientation_of(const OdeState& x) { return {x[0], x[1], x[2], x[3]}; }

void normalise(OdeState& x) {
  const double n = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
  for (int i = 0; i < 4; ++i) x[i] /= n;
}

// Both frames, like aloft's kernel (study/full_flight_simulation.hpp): body axes from
// q_j^-1 q_{j+1}, world axes from q_{j+1} q_j^-1.
RmsDaByFrame odeint_rms_da_deg(const StudyFlight& f, const TorqueFreeBody& body, std::size_t k) {
  boost::numeric::odeint::runge_kutta4<OdeState> stepper;
  const std::size_t n = f.samples();
  const Eigen::Quaterniond& q = f.orientation[k];
  const Eigen::Vector3d& w = f.state_omega_body[k];
  const OdeState seed = {q.w(), q.x(), q.y(), q.z(), w.x(), w.y(), w.z()};
  double body_sq = 0.0, world_sq = 0.0;
  const auto add = [&](const Eigen::Quaterniond& from, const Eigen::Quaterniond& to, std::size_t j) {
    const double b = aloft::deviation_angle(rotation_axis_between(from, to), f.measured_omega_body[j]);
    const double w = aloft::deviation_angle(world_rotation_axis_between(from, to), f.measured_omega_world[j]);
    body_sq += b * b;
    world_sq += w * w;
  };
  OdeState x = seed;
  for (std::size_t j = k; j + 1 < n; ++j) {
    const double dt = f.time_s[j + 1] - f.time_s[j];
    const Eigen::Quaterniond before = orientation_of(x);
    stepper.do_step(body, x, f.time_s[j], dt);
    normalise(x);
    add(before, orientation_of(x), j);
  }
  x = seed;
  for (std::size_t j = k; j-- > 0;) {
    const double dt = f.time_s[j + 1] - f.time_s[j];
    const Eigen::Quaterniond after = orientation_of(x);
    stepper.do_step(body, x, f.time_s[j + 1], -dt);
    normalise(x);
    add(orientation_of(x), after, j);
  }
  const double to_deg = 180.0 / M_PI, intervals = static_cast<double>(n - 1);
  return {std::sqrt(body_sq / intervals) * to_deg, std::sqrt(world_sq / intervals) * to_deg};
}

void BM_GfAnalysis_OdeintRk4(benchmark::State& state) {
  const BuiltInTrial& t = trial();
  const TorqueFreeBody body{t.body.inertia.tensor(), t.body.inertia.inverse()};
  // The two implementations must agree before their speed is compared.
  const RmsDaByFrame aloft_result = full_flight_rms_da_deg(t.flight, t.body.inertia, 100);
  const RmsDaByFrame odeint_result = odeint_rms_da_deg(t.flight, body, 100);
  for (std::size_t f = 0; f < kDaFrames; ++f) {
    if (std::abs(aloft_result[f] - odeint_result[f]) > 1e-6 * aloft_result[f]) {
      state.SkipWithError("odeint and aloft disagree");
      return;
    }
  }
  for (auto _ : state) {
    double sum = 0.0;
    for (std::size_t k = 0; k < t.flight.samples(); ++k) sum += odeint_rms_da_deg(t.flight, body, k)[0];
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(t.flight.samples()));
  state.SetLabel("items = full-flight simulations");
}

}  // namespace

BENCHMARK(BM_GfAnalysis_AloftRk4)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GfAnalysis_OdeintRk4)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
