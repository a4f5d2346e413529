// `internal_momentum`: a rotor, fan or wheel spinning inside the body at a steady rate (a
// gyrostat): an angular momentum h fixed in body axes, I·dw/dt + w × (I·w + h) = 0.
// theta = I_nom⁻¹ h (rad/s: the body rate that would carry h), so that a unit change
// moves the readings by about |w| t.
//
// What tells it from its look-alikes (docs/diagnose.md, "A rotor inside"): its torque
// -w × h follows w over the whole flight (an impulse is a step at one instant); it scales
// with |w| (wrong moments with |w|²); and on a body of revolution, h along the axis is,
// within one flight, exactly an axial moment changed by h / w_axis
// (4_judge/momentum_moment_equivalence.hpp): flights thrown at different axial rates part
// the two, so a session is where a rotor can be named (`named_only_when_told_apart`).
#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/2_model/momentum_from_readings.hpp"
#include "common/printf_text.hpp"

namespace aloft::host::diagnose {
namespace {

// Pinned when theta's standard error is below 1 % of the mean |w|: |h| to 1 % of |L|, a
// fifth of the 5 % rotor the generator draws on average (0.5-10 %).
double tolerance(double mean_speed, double) { return 0.01 * mean_speed; }

void apply(const Eigen::VectorXd& theta, const NominalInertia& nominal, ModelTerms& terms) {
  terms.momentum = nominal.tensor * theta.head<3>();
}

EffectParameters parameters(const Eigen::VectorXd& theta, const NominalInertia& nominal, double) {
  EffectParameters p;
  p.vector = nominal.tensor * theta.head<3>();
  return p;
}

// |h| below 0.2 % of the |L| the mean |w| carries: the rotor's torque then turns w by less
// than the smallest rotor the generator draws (0.5 %) does, by a factor of 2.5.
std::string too_small(const EffectParameters& p, const SignificanceScale& scale) {
  if (scale.nominal == nullptr) return {};
  const double size = (scale.nominal->tensor.inverse() * p.vector).norm() / scale.speed;
  if (size < 0.002) return printf_text("its |h| is %.2g %% of the body's |L|", 100.0 * size);
  return {};
}

}  // namespace

constexpr EffectDescriptor internal_momentum_effect = [] {
  EffectDescriptor d;
  d.name = "internal_momentum";
  d.parameter_count = 3;
  // Within a flight h mimics an impulse, a gyro bias (h = I·b to first order) and, along
  // a body of revolution's axis, an axial moment: tried as an ordinary candidate it took
  // the withheld imu_impulse_4, three practice2 compound flights and a step of the first
  // real racquet session (docs/diagnose.md, "A rotor inside").
  d.named_only_when_told_apart = true;
  // Alone on a body whose moments are also wrong, each flight's h takes up part of the
  // moment error by its own rate (a moment error scales with w², a rotor with w).
  d.jointly_with = Effect::inertia_moments;
  // From zero, a rotor of 15-40 % of |L| stopped in another minimum on 6 of 40 generated
  // flights (at 1e4-1e5 times the true minimum's cost); from the balance of the Euler
  // equations it does not (docs/diagnose.md, "A rotor inside").
  d.start_from_readings = momentum_theta_from_readings;
  d.hooks = {tolerance, apply, parameters, too_small, no_objection, no_physics_objection};
  return d;
}();

}  // namespace aloft::host::diagnose
