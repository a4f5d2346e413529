// `impulse`: a short external torque during flight, an angular impulse I_nom dw (body
// axes) at one time. theta = dw (rad/s); the time is not a smooth parameter (the jump
// moves from one sample to the next), so start_search.cpp searches it, and the ranking
// charges it as a parameter all the same.
#include "diagnose/2_model/effect_descriptor.hpp"
#include "common/printf_text.hpp"

namespace aloft::host::diagnose {
namespace {

double tolerance(double, double) { return 0.05; }  // rad/s of jump

void apply(const Eigen::VectorXd& theta, const NominalInertia&, ModelTerms& terms) {
  terms.has_jump = true;
  terms.jump = theta.head<3>();
}

EffectParameters parameters(const Eigen::VectorXd& theta, const NominalInertia& nominal,
                            double impulse_time_s) {
  EffectParameters p;
  p.vector = nominal.tensor * theta.head<3>();
  p.time_s = impulse_time_s;
  return p;
}

// |dw| below 0.5 % of the mean |w|.
std::string too_small(const EffectParameters& p, const SignificanceScale& scale) {
  if (scale.nominal == nullptr) return {};
  const double jump = (scale.nominal->tensor.inverse() * p.vector).norm() / scale.speed;
  if (jump < 0.005) return printf_text("its jump is %.2g %% of |w|", 100.0 * jump);
  return {};
}

}  // namespace

constexpr EffectDescriptor impulse_effect = [] {
  EffectDescriptor d;
  d.name = "impulse";
  d.parameter_count = 3;
  d.searched_parameters = 1;
  d.shared_by_flights = false;
  d.hooks = {tolerance, apply, parameters, too_small, no_objection, no_physics_objection};
  return d;
}();

}  // namespace aloft::host::diagnose
