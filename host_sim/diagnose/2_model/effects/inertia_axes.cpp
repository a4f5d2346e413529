// `inertia_axes`: the principal axes are rotated from nominal. theta = d, a rotation
// vector (rad, body axes): I = R(d) I R(d)^T. From a gyro alone it is the same as a
// rotated sensor (SPEC §4): a rotated tensor and a rotated sensor give the same readings.
#include "aloft/dynamics/rotation.hpp"
#include "diagnose/2_model/canonical_rotation.hpp"
#include "diagnose/2_model/effect_descriptor.hpp"
#include "common/printf_text.hpp"

namespace aloft::host::diagnose {
namespace {

double tolerance(double, double) { return 1.0 / (180.0 / 3.14159265358979323846); }  // 1 degree

// Turns the tensor as it stands (after any change of the moments).
void apply(const Eigen::VectorXd& theta, const NominalInertia&, ModelTerms& terms) {
  const Eigen::Matrix3d r = quat_exp<double>(theta.head<3>()).toRotationMatrix();
  terms.inertia = r * terms.inertia * r.transpose();
}

EffectParameters parameters(const Eigen::VectorXd& theta, const NominalInertia& nominal, double) {
  EffectParameters p;
  describe_rotation(p, theta, nominal, true);
  describe_inertia(p, nominal.principal_moments,
                   p.rotation.toRotationMatrix() * nominal.principal_axes.toRotationMatrix(), nominal);
  return p;
}

// Turned by less than 0.25°.
std::string too_small(const EffectParameters& p, const SignificanceScale&) {
  if (p.angle_deg < 0.25) return printf_text("it turns the axes by only %.2g deg", p.angle_deg);
  return {};
}

}  // namespace

constexpr EffectDescriptor inertia_axes_effect = [] {
  EffectDescriptor d;
  d.name = "inertia_axes";
  d.parameter_count = 3;
  d.rotation_gauge = true;
  d.gyro_equivalents = {Effect::sensor_misalignment};
  d.hooks = {tolerance, apply, parameters, too_small, no_objection, no_physics_objection};
  return d;
}();

}  // namespace aloft::host::diagnose
