// `sensor_misalignment`: the sensor axes are rotated from the body axes. theta = m, a
// rotation vector (rad): sensor->body becomes q_imu * exp(m). From a gyro alone it is the
// same as rotated principal axes (SPEC §4).
#include "aloft/dynamics/rotation.hpp"
#include "diagnose/2_model/canonical_rotation.hpp"
#include "diagnose/2_model/effect_descriptor.hpp"
#include "common/printf_text.hpp"

namespace aloft::host::diagnose {
namespace {

double tolerance(double, double) { return 1.0 / (180.0 / 3.14159265358979323846); }  // 1 degree

void apply(const Eigen::VectorXd& theta, const NominalInertia&, ModelTerms& terms) {
  terms.misaligned = true;
  terms.misalignment = quat_exp<double>(theta.head<3>());
}

EffectParameters parameters(const Eigen::VectorXd& theta, const NominalInertia& nominal, double) {
  EffectParameters p;
  describe_rotation(p, theta, nominal, false);
  return p;
}

// Turned by less than 0.25°.
std::string too_small(const EffectParameters& p, const SignificanceScale&) {
  if (p.angle_deg < 0.25) return printf_text("it turns the axes by only %.2g deg", p.angle_deg);
  return {};
}

}  // namespace

constexpr EffectDescriptor sensor_misalignment_effect = [] {
  EffectDescriptor d;
  d.name = "sensor_misalignment";
  d.parameter_count = 3;
  d.sensor = true;
  d.rotation_gauge = true;
  d.gyro_equivalents = {Effect::inertia_axes};
  d.hooks = {tolerance, apply, parameters, too_small, no_objection, no_physics_objection};
  return d;
}();

}  // namespace aloft::host::diagnose
