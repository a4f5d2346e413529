#include "diagnose/flight_model.hpp"

#include <algorithm>
#include <cmath>

#include "diagnose/effect_descriptor.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using State = Eigen::Matrix<double, 6, 1>;  // body rate, then the rotor's rate (damping only)

// Longest integration step: RK4 at 5 ms keeps the relative error of a 15 rad/s motion
// near 1e-6 over a second, far below any gyro's noise; 1 kHz data takes one step a sample.
constexpr double kMaxStep = 0.005;

// The slice of theta that belongs to `effect` (empty when it is not in the model).
Eigen::VectorXd slice_of(const EffectModel& model, const Eigen::VectorXd& theta, Effect effect) {
  const int offset = theta_offset(model, effect);
  if (offset < 0) return Eigen::VectorXd();
  return theta.segment(offset, effect_parameter_count(effect));
}

// Everything a flight needs from (model, theta), computed once per prediction.
class FlightDynamics {
 public:
  FlightDynamics(const ModelTerms& terms, const Flight& flight)
      : inertia_(terms.inertia),
        drag_(terms.drag),
        rotor_(terms.rotor),
        rotor_rate_(terms.rotor_rate),
        has_jump_(terms.has_jump),
        time_factor_(terms.time_factor),
        jump_(terms.jump),
        bias_(terms.bias),
        scale_(terms.scale) {
    const Mat3 sensor_to_body = flight.sensor_to_body.toRotationMatrix();
    sensor_rotation_ = terms.misaligned ? Mat3(sensor_to_body * terms.misalignment.toRotationMatrix()) : sensor_to_body;
    // The shell carries the nominal tensor less the rotor, so that with the rotor locked
    // the body is the nominal one.
    shell_ = inertia_ - rotor_ * Mat3::Identity();
    shell_inverse_ = shell_.inverse();
    body_to_sensor_ = sensor_rotation_.transpose();
  }

  bool has_rotor() const { return rotor_ > 0.0; }
  bool has_jump() const { return has_jump_; }
  double time_factor() const { return time_factor_; }

  State rate(const State& x) const {
    const Vec3 w = x.head<3>();
    Vec3 torque = (shell_ * w).cross(w);
    if (drag_ != 0.0) torque -= drag_ * w.norm() * w;
    State dx;
    if (has_rotor()) {
      const Vec3 wr = x.tail<3>();
      const Vec3 coupling = rotor_rate_ * rotor_ * (wr - w);
      dx.head<3>() = shell_inverse_ * (torque + coupling);
      dx.tail<3>() = -w.cross(wr) - rotor_rate_ * (wr - w);
    } else {
      dx.head<3>() = shell_inverse_ * torque;
      dx.tail<3>().setZero();
    }
    return dx;
  }

  // Body rate alone, for every effect but the rotor's (the common, hot case).
  Vec3 rigid_rate(const Vec3& w) const {
    Vec3 torque = (shell_ * w).cross(w);
    if (drag_ != 0.0) torque -= drag_ * w.norm() * w;
    return shell_inverse_ * torque;
  }

  void rk4(State& x, double h) const {
    if (!has_rotor()) {
      const Vec3 w = x.head<3>();
      const Vec3 k1 = rigid_rate(w);
      const Vec3 k2 = rigid_rate(w + 0.5 * h * k1);
      const Vec3 k3 = rigid_rate(w + 0.5 * h * k2);
      const Vec3 k4 = rigid_rate(w + h * k3);
      x.head<3>() = w + (h / 6.0) * (k1 + 2.0 * (k2 + k3) + k4);
      return;
    }
    const State k1 = rate(x);
    const State k2 = rate(x + 0.5 * h * k1);
    const State k3 = rate(x + 0.5 * h * k2);
    const State k4 = rate(x + h * k3);
    x += (h / 6.0) * (k1 + 2.0 * (k2 + k3) + k4);
  }

  // Integrates over [from, to] (either direction) in steps of at most kMaxStep.
  void advance(State& x, double from, double to) const {
    const double span = to - from;
    const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(span) / kMaxStep - 1e-9)));
    const double h = span / steps;
    for (int i = 0; i < steps; ++i) rk4(x, h);
  }

  // The impulse changes L by I_nom dw; forwards adds it, backwards takes it away.
  void apply_jump(State& x, double sign) const {
    x.head<3>() += sign * (shell_inverse_ * (nominal_impulse_scale_ * jump_));
  }
  void set_impulse_scale(const Mat3& nominal_tensor) { nominal_impulse_scale_ = nominal_tensor; }

  Vec3 reading(const State& x) const {
    return scale_.cwiseProduct(body_to_sensor_ * x.head<3>()) + bias_;
  }

 private:
  Mat3 inertia_;
  Mat3 sensor_rotation_;
  Mat3 shell_;
  Mat3 shell_inverse_;
  Mat3 body_to_sensor_;
  Mat3 nominal_impulse_scale_ = Mat3::Identity();
  double drag_ = 0.0;
  double rotor_ = 0.0;
  double rotor_rate_ = 0.0;
  bool has_jump_ = false;
  double time_factor_ = 1.0;
  Vec3 jump_ = Vec3::Zero();
  Vec3 bias_ = Vec3::Zero();
  Vec3 scale_ = Vec3::Ones();
};

}  // namespace

std::size_t reference_index(Effect effect, const Flight& flight) {
  if (describe(effect).starts_at_release || flight.size() == 0) return 0;
  return flight.size() / 2;
}

Eigen::Vector3d body_rate_of_reading(const Flight& flight, const Eigen::Vector3d& reading) {
  return flight.sensor_to_body * reading;
}

std::size_t compound_reference_index(const EffectModel& model, const Flight& flight) {
  for (Effect e : model_effects(model)) {
    if (describe(e).starts_at_release) return reference_index(e, flight);
  }
  return reference_index(Effect::none, flight);
}

std::vector<Effect> model_effects(const EffectModel& model) {
  std::vector<Effect> effects;
  for (Effect e : model.base) {
    if (e != Effect::none) effects.push_back(e);
  }
  if (model.effect != Effect::none) effects.push_back(model.effect);
  return effects;
}

int theta_offset(const EffectModel& model, Effect effect) {
  int offset = 0;
  for (Effect e : model_effects(model)) {
    if (e == effect) return offset;
    offset += effect_parameter_count(e);
  }
  return -1;
}

int model_parameter_count(const EffectModel& model) {
  int count = 0;
  for (Effect e : model_effects(model)) count += effect_parameter_count(e);
  return count;
}

ModelTerms model_terms(const EffectModel& model, const Eigen::VectorXd& theta) {
  ModelTerms terms(model.nominal);
  const std::vector<Effect> effects = model_effects(model);
  for (bool first : {true, false}) {
    for (Effect e : effects) {
      const EffectDescriptor& d = describe(e);
      if (d.sets_tensor == first) d.hooks.apply(slice_of(model, theta, e), model.nominal, terms);
    }
  }
  return terms;
}

Eigen::Vector3d body_rate_for_reading(const EffectModel& model, const Flight& flight,
                                      const Eigen::VectorXd& theta, const Eigen::Vector3d& reading) {
  // The sensor model backwards: take the bias off, undo the scale, then the rotation.
  const ModelTerms terms = model_terms(model, theta);
  Vec3 w = reading - terms.bias;
  w = w.cwiseQuotient(terms.scale);
  if (terms.misaligned) w = terms.misalignment * w;
  return flight.sensor_to_body * w;
}

void predict_readings(const EffectModel& model, const Flight& flight, std::size_t ref,
                      const Eigen::Vector3d& omega_ref, const Eigen::VectorXd& theta,
                      std::vector<Eigen::Vector3d>& readings) {
  const std::size_t n = flight.size();
  readings.resize(n);
  if (n == 0) return;
  FlightDynamics dynamics(model_terms(model, theta), flight);
  dynamics.set_impulse_scale(model.nominal.tensor);
  const bool has_jump = dynamics.has_jump();
  const double t_ref = flight.time_s[ref];
  // True (simulation) time of a recorded time stamp; differs only under clock drift.
  auto true_time = [&](double t) { return t_ref + (t - t_ref) * dynamics.time_factor(); };
  const double t_jump = has_jump ? true_time(model.impulse_time_s) : 0.0;

  State start;
  start.head<3>() = omega_ref;
  start.tail<3>() = omega_ref;  // rotor co-rotating at the reference (damping only)
  readings[ref] = dynamics.reading(start);

  // Forwards from the reference, then backwards; an impulse strictly between two samples
  // (or on the later one) is applied where it falls.
  State x = start;
  for (std::size_t k = ref + 1; k < n; ++k) {
    const double a = true_time(flight.time_s[k - 1]);
    const double b = true_time(flight.time_s[k]);
    if (has_jump && t_jump > a && t_jump <= b) {
      dynamics.advance(x, a, t_jump);
      dynamics.apply_jump(x, 1.0);
      if (b > t_jump) dynamics.advance(x, t_jump, b);
    } else {
      dynamics.advance(x, a, b);
    }
    readings[k] = dynamics.reading(x);
  }
  x = start;
  for (std::size_t k = ref; k-- > 0;) {
    const double a = true_time(flight.time_s[k + 1]);
    const double b = true_time(flight.time_s[k]);
    if (has_jump && t_jump > b && t_jump <= a) {
      if (a > t_jump) dynamics.advance(x, a, t_jump);
      dynamics.apply_jump(x, -1.0);
      dynamics.advance(x, t_jump, b);
    } else {
      dynamics.advance(x, a, b);
    }
    readings[k] = dynamics.reading(x);
  }
}

EffectParameters effect_parameters(const EffectModel& model, const Eigen::VectorXd& theta) {
  return effect_parameters(model, theta, model.effect);
}

EffectParameters effect_parameters(const EffectModel& model, const Eigen::VectorXd& all_theta, Effect effect) {
  const Eigen::VectorXd theta = slice_of(model, all_theta, effect);
  if (theta.size() != effect_parameter_count(effect)) return EffectParameters();
  return describe(effect).hooks.parameters(theta, model.nominal, model.impulse_time_s);
}

}  // namespace aloft::host::diagnose
