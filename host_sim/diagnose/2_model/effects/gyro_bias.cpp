// `gyro_bias`: measured = true + b. theta = b (rad/s, sensor axes).
#include "diagnose/2_model/effect_descriptor.hpp"
#include "common/printf_text.hpp"

namespace aloft::host::diagnose {
namespace {

double tolerance(double, double) { return 0.01; }  // rad/s

void apply(const Eigen::VectorXd& theta, const NominalInertia&, ModelTerms& terms) {
  terms.bias = theta.head<3>();
}

EffectParameters parameters(const Eigen::VectorXd& theta, const NominalInertia&, double) {
  EffectParameters p;
  p.vector = theta.head<3>();
  return p;
}

// |b| below 0.1 % of the mean |w|.
std::string too_small(const EffectParameters& p, const SignificanceScale& scale) {
  if (p.vector.norm() < 0.001 * scale.speed) return printf_text("its bias is %.2g rad/s", p.vector.norm());
  return {};
}

}  // namespace

constexpr EffectDescriptor gyro_bias_effect = [] {
  EffectDescriptor d;
  d.name = "gyro_bias";
  d.parameter_count = 3;
  d.sensor = true;
  d.hooks = {tolerance, apply, parameters, too_small, no_objection, no_physics_objection};
  return d;
}();

}  // namespace aloft::host::diagnose
