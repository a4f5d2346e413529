// `clock_drift`: recorded time = true time * (1 + eps). theta = eps: a recorded time t
// maps to true time t_ref + (t - t_ref)/(1+eps). From a gyro alone it is the same as a
// uniform gyro_scale (SPEC §4): a torque-free motion sped up by (1+eps) is the same
// motion with every rate scaled by (1+eps).
#include <cmath>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "common/printf_text.hpp"

namespace aloft::host::diagnose {
namespace {

double tolerance(double, double) { return 0.005; }

void apply(const Eigen::VectorXd& theta, const NominalInertia&, ModelTerms& terms) {
  terms.time_factor = 1.0 / (1.0 + theta(0));
}

EffectParameters parameters(const Eigen::VectorXd& theta, const NominalInertia&, double) {
  EffectParameters p;
  p.rate_error = theta(0);
  return p;
}

// A rate error below 0.1 %.
std::string too_small(const EffectParameters& p, const SignificanceScale&) {
  if (std::abs(p.rate_error) < 0.001) return printf_text("its rate error is %.2g %%", 100.0 * p.rate_error);
  return {};
}

// No real clock runs that far off.
std::string senseless(const EffectParameters& p) {
  if (!(std::abs(p.rate_error) > kLargestSensibleScaleError)) return {};
  return printf_text("ruled out: a clock %+.0f %% off is beyond any real clock", 100.0 * p.rate_error);
}

}  // namespace

constexpr EffectDescriptor clock_drift_effect = [] {
  EffectDescriptor d;
  d.name = "clock_drift";
  d.parameter_count = 1;
  d.sensor = true;
  d.gyro_equivalents = {Effect::gyro_scale};
  d.hooks = {tolerance, apply, parameters, too_small, senseless, no_physics_objection};
  return d;
}();

}  // namespace aloft::host::diagnose
