// `none`: the nominal model as it is (the gap is measurement noise only). Registered like
// the others so that every question about an effect has an answer for it too.
#include "diagnose/2_model/effect_descriptor.hpp"

namespace aloft::host::diagnose {
namespace {

double tolerance(double, double) { return 1.0; }

void apply(const Eigen::VectorXd&, const NominalInertia&, ModelTerms&) {}

EffectParameters parameters(const Eigen::VectorXd&, const NominalInertia&, double) { return {}; }

std::string too_small(const EffectParameters&, const SignificanceScale&) { return {}; }

}  // namespace

constexpr EffectDescriptor none_effect = [] {
  EffectDescriptor d;
  d.name = "none";
  d.parameter_count = 0;
  d.hooks = {tolerance, apply, parameters, too_small, no_objection, no_physics_objection};
  return d;
}();

}  // namespace aloft::host::diagnose
