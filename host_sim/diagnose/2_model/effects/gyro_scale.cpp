// `gyro_scale`: measured_i = (1 + s_i) true_i. theta = s (sensor axes).
#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/2_model/moment_scale_equivalence.hpp"
#include "common/printf_text.hpp"

namespace aloft::host::diagnose {
namespace {

double tolerance(double, double) { return 0.005; }

void apply(const Eigen::VectorXd& theta, const NominalInertia&, ModelTerms& terms) {
  terms.scale += theta.head<3>();
}

EffectParameters parameters(const Eigen::VectorXd& theta, const NominalInertia&, double) {
  EffectParameters p;
  p.vector = theta.head<3>();
  return p;
}

// Every error below 0.1 %.
std::string too_small(const EffectParameters& p, const SignificanceScale&) {
  if (p.vector.cwiseAbs().maxCoeff() < 0.001) return printf_text("its scale errors are below %.2g %%", 0.1);
  return {};
}

// No phone or MEMS gyro is off by more than that; a fit that needs it mimics another effect.
std::string senseless(const EffectParameters& p) {
  Eigen::Index axis = 0;
  if (!(p.vector.cwiseAbs().maxCoeff(&axis) > kLargestSensibleScaleError)) return {};
  return printf_text("ruled out: a gyro scale error of %+.0f %% is beyond any real gyro (limit %.0f %%)",
                     100.0 * p.vector(axis), 100.0 * kLargestSensibleScaleError);
}

// A scale reproduces wrong moments exactly where the gyro reads the principal axes and the
// fitted moments keep the nominal order (moment_scale_equivalence.hpp).
bool mimics_moments(const EffectParameters& moments, const NominalInertia& nominal,
                    const Eigen::Quaterniond& sensor_to_body) {
  return gyro_along_principal_axes(nominal.principal_axes, sensor_to_body) &&
         scale_mimicking_moments(nominal.principal_moments, moments.principal_kg_m2).has_value();
}

}  // namespace

constexpr EffectDescriptor gyro_scale_effect = [] {
  EffectDescriptor d;
  d.name = "gyro_scale";
  d.parameter_count = 3;
  d.sensor = true;
  d.one_way_equivalent = {Effect::inertia_moments, mimics_moments};
  d.hooks = {tolerance, apply, parameters, too_small, senseless, no_physics_objection};
  return d;
}();

}  // namespace aloft::host::diagnose
