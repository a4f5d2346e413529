#include "diagnose/2_model/reading_derivatives.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "diagnose/2_model/flight_dynamics.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// Step of the central differences of the terms along theta: the sensor terms are linear
// in theta or a quaternion exponential, whose O(h^2) error at 1e-5 is ~1e-10 relative, as
// is the rounding (eps / h); the columns they replace were forward differences of whole
// simulations, good to ~1e-7.
constexpr double kTermStep = 1e-5;

// The terms with theta moved by the step either way along parameter i.
struct NudgedTerms {
  double h;  // the step
  ModelTerms up, down;
};
NudgedTerms nudged_terms(const EffectModel& model, const Eigen::VectorXd& theta, Eigen::Index i) {
  const double h = kTermStep * std::max(1.0, std::abs(theta(i)));
  Eigen::VectorXd up = theta, down = theta;
  up(i) += h;
  down(i) -= h;
  return {h, model_terms(model, up), model_terms(model, down)};
}

// The rotation's terms other than the impulse's jump are the same.
bool same_motion_but_jump(const ModelTerms& a, const ModelTerms& b) {
  return a.inertia == b.inertia && a.drag == b.drag && a.rotor == b.rotor && a.rotor_rate == b.rotor_rate &&
         a.momentum == b.momentum && a.time_factor == b.time_factor;
}

bool same_sensor(const ModelTerms& a, const ModelTerms& b) {
  return a.scale == b.scale && a.bias == b.bias && a.misaligned == b.misaligned &&
         a.misalignment.coeffs() == b.misalignment.coeffs();
}

// Whether moving theta along direction i changes the sensor's terms and nothing else.
bool moves_sensor_only(const ModelTerms& up, const ModelTerms& down) {
  return same_motion_but_jump(up, down) && up.has_jump == down.has_jump && up.jump == down.jump &&
         up.misaligned == down.misaligned && !same_sensor(up, down);
}

}  // namespace

std::vector<char> sensor_directions(const EffectModel& model, const Eigen::VectorXd& theta) {
  std::vector<char> out(static_cast<std::size_t>(theta.size()), 0);
  for (Eigen::Index i = 0; i < theta.size(); ++i) {
    const NudgedTerms t = nudged_terms(model, theta, i);
    out[static_cast<std::size_t>(i)] = moves_sensor_only(t.up, t.down);
  }
  return out;
}

void sensor_reading_derivatives(const EffectModel& model, const Flight& flight, const Eigen::VectorXd& theta,
                                const std::vector<Eigen::Vector3d>& readings,
                                const std::vector<char>& directions, Eigen::MatrixXd& columns) {
  const std::size_t n = flight.size();
  const FlightDynamics at(model_terms(model, theta), flight);
  std::vector<Vec3> rates(n);
  for (std::size_t k = 0; k < n; ++k) rates[k] = at.rate_of_reading(readings[k]);
  for (Eigen::Index i = 0; i < theta.size(); ++i) {
    if (!directions[static_cast<std::size_t>(i)]) continue;
    const NudgedTerms t = nudged_terms(model, theta, i);
    const double h = t.h;
    const FlightDynamics a(t.up, flight), b(t.down, flight);
    // reading = scale (B w) + bias, differentiated with w held.
    const Mat3 d_sensor = (a.body_to_sensor() - b.body_to_sensor()) / (2.0 * h);
    const Vec3 d_scale = (a.scale() - b.scale()) / (2.0 * h), d_bias = (a.bias() - b.bias()) / (2.0 * h);
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& w = rates[k];
      columns.block<3, 1>(static_cast<Eigen::Index>(3 * k), i) =
          d_scale.cwiseProduct(at.body_to_sensor() * w) + at.scale().cwiseProduct(d_sensor * w) + d_bias;
    }
  }
}

std::vector<char> impulse_directions(const EffectModel& model, const Eigen::VectorXd& theta) {
  std::vector<char> out(static_cast<std::size_t>(theta.size()), 0);
  for (Eigen::Index i = 0; i < theta.size(); ++i) {
    const NudgedTerms t = nudged_terms(model, theta, i);
    out[static_cast<std::size_t>(i)] = same_motion_but_jump(t.up, t.down) && t.up.has_jump &&
                                       t.down.has_jump && same_sensor(t.up, t.down) &&
                                       t.up.jump != t.down.jump;
  }
  return out;
}

void impulse_reading_derivatives(const EffectModel& model, const Flight& flight, std::size_t ref,
                                 const Eigen::VectorXd& theta, const Eigen::Matrix3d& impulse_rate_derivative,
                                 const std::vector<char>& directions, Eigen::MatrixXd& jacobian) {
  const std::size_t n = flight.size();
  const Eigen::Index rates = theta.size();
  const FlightDynamics at(model_terms(model, theta), flight);
  const double t_ref = flight.time_s[ref];
  const auto true_time = [&](double t) { return t_ref + (t - t_ref) * at.time_factor(); };
  const double t_jump = true_time(model.impulse_time_s);
  // The walk that meets the impulse adds it going forwards and takes it away going
  // backwards; past it, a change of the rate there is carried as a change of omega_ref
  // would be, by the flow map: d reading_k / d rate_at_impulse = G_k Phi_j^-1.
  const double sign = t_jump > t_ref ? 1.0 : -1.0;
  const Mat3 carried = impulse_rate_derivative.inverse() * at.shell_inverse() * model.nominal.tensor;
  // Each marked column's carried change, then each sample once for all of them: which
  // side of the impulse it is on, and its rate rows read once (case00 408.8 -> 407.1 M
  // instructions against a pass over the samples per column).
  std::vector<std::pair<Eigen::Index, Vec3>> marked;
  for (Eigen::Index i = 0; i < theta.size(); ++i) {
    if (!directions[static_cast<std::size_t>(i)]) continue;
    const NudgedTerms t = nudged_terms(model, theta, i);
    const Vec3 d_jump = (t.up.jump - t.down.jump) / (2.0 * t.h);
    marked.emplace_back(i, sign * (carried * d_jump));
  }
  for (std::size_t k = 0; k < n; ++k) {
    const double t = true_time(flight.time_s[k]);
    const bool past = sign > 0.0 ? t >= t_jump : t < t_jump;
    const Eigen::Index row = static_cast<Eigen::Index>(3 * k);
    for (const auto& [i, c] : marked) {
      if (past) {
        jacobian.block<3, 1>(row, i) = jacobian.block<3, 3>(row, rates) * c;
      } else {
        jacobian.block<3, 1>(row, i).setZero();
      }
    }
  }
}

}  // namespace aloft::host::diagnose
