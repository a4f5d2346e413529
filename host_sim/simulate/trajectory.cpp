#include "simulate/trajectory.hpp"

#include <cmath>

#include "aloft/dynamics/rk4_integrator.hpp"
#include "aloft/dynamics/splitting_integrator.hpp"
#include "common/commands.hpp"

namespace aloft::host {
namespace {

template <typename Scalar>
InertiaTensor<Scalar> convert(const InertiaTensor<double>& inertia) {
  InertiaTensor<Scalar> out;
  const Status s = InertiaTensor<Scalar>::make_from_tensor(inertia.tensor().cast<Scalar>(), out);
  if (s != Status::ok) throw Error(std::string("inertia in single precision: ") + describe(s));
  return out;
}

template <typename Scalar, typename Integrator>
std::vector<TrajectorySample> run(const Integrator& integrator, const TrajectoryRequest& request,
                                  std::size_t samples, int substeps) {
  RigidBodyState<Scalar> state;
  state.orientation = request.initial.orientation.cast<Scalar>();
  state.omega_body = request.initial.omega_body.cast<Scalar>();
  const double dt = 1.0 / request.rate_hz;
  const Scalar h = static_cast<Scalar>(dt / substeps);
  std::vector<TrajectorySample> out;
  out.reserve(samples);
  for (std::size_t k = 0; k < samples; ++k) {
    if (k > 0) {
      for (int i = 0; i < substeps; ++i) {
        const Status s = integrator.step(state, h);
        if (s != Status::ok) {
          throw Error("simulation stopped at t = " + std::to_string(double(k) * dt) + " s: " + describe(s));
        }
      }
    }
    RigidBodyState<double> sample;
    sample.orientation = state.orientation.template cast<double>();
    sample.omega_body = state.omega_body.template cast<double>();
    // k / rate, not k * dt: the time is then the double nearest the exact instant
    // (3 / 200 is 0.015; 3 * 0.005 is 0.015000000000000001).
    out.push_back({double(k) / request.rate_hz, sample});
  }
  return out;
}

template <typename Scalar>
std::vector<TrajectorySample> run_in(const InertiaTensor<Scalar>& inertia, const TrajectoryRequest& request,
                                     std::size_t samples, int substeps) {
  if (request.integrator == IntegratorKind::rk4) {
    return run<Scalar>(Rk4Integrator<Scalar>(inertia), request, samples, substeps);
  }
  return run<Scalar>(SplittingIntegrator<Scalar>(inertia), request, samples, substeps);
}

}  // namespace

TrajectoryRequest simulate_request(const Eigen::Vector3d& w0, const Eigen::Vector4d& q0_wxyz,
                                   double duration_s, double rate_hz, const std::string& integrator,
                                   bool single_precision) {
  TrajectoryRequest request;
  request.initial.omega_body = w0;
  request.initial.orientation = Eigen::Quaterniond(q0_wxyz[0], q0_wxyz[1], q0_wxyz[2], q0_wxyz[3]);
  if (!aloft::is_unit(request.initial.orientation)) {
    throw Error("--q0: quaternion is not of unit length");
  }
  request.initial.orientation.normalize();
  request.duration_s = duration_s;
  request.rate_hz = rate_hz;
  request.integrator = integrator_from_name(integrator);
  request.precision = single_precision ? Precision::single_precision : Precision::double_precision;
  return request;
}

IntegratorKind integrator_from_name(const std::string& name) {
  if (name == "rk4") return IntegratorKind::rk4;
  if (name == "splitting") return IntegratorKind::splitting;
  throw Error("unknown integrator \"" + name + "\" (rk4 or splitting)");
}

std::vector<TrajectorySample> simulate_trajectory(const InertiaTensor<double>& inertia,
                                                  const TrajectoryRequest& request) {
  if (!(std::isfinite(request.duration_s) && request.duration_s >= 0.0)) {
    throw Error("duration must be a finite number >= 0");
  }
  if (!(std::isfinite(request.rate_hz) && request.rate_hz > 0.0)) {
    throw Error("rate must be a finite number > 0");
  }
  if (!(request.max_step_s > 0.0)) throw Error("maximum step must be > 0");
  const Status s = validate(request.initial);
  if (s != Status::ok) throw Error(std::string("initial state: ") + describe(s));
  const double samples_f = std::floor(request.duration_s * request.rate_hz + 1e-9) + 1.0;
  if (samples_f > 1e8) throw Error("too many samples (duration x rate > 1e8)");
  const auto samples = static_cast<std::size_t>(samples_f);
  const int substeps = static_cast<int>(std::ceil(1.0 / request.rate_hz / request.max_step_s - 1e-9));
  if (request.precision == Precision::double_precision) {
    return run_in<double>(inertia, request, samples, substeps);
  }
  return run_in<float>(convert<float>(inertia), request, samples, substeps);
}

}  // namespace aloft::host
