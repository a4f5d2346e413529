#include "diagnose/2_model/effect_model.hpp"

#include "diagnose/2_model/effect_descriptor.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

// The slice of theta that belongs to `effect` (empty when it is not in the model).
Eigen::VectorXd slice_of(const EffectModel& model, const Eigen::VectorXd& theta, Effect effect) {
  const int offset = theta_offset(model, effect);
  if (offset < 0) return Eigen::VectorXd();
  return theta.segment(offset, effect_parameter_count(effect));
}

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

bool has_searched_time(const EffectModel& model) {
  for (Effect e : model_effects(model)) {
    if (describe(e).searched_parameters > 0) return true;
  }
  return false;
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

EffectParameters effect_parameters(const EffectModel& model, const Eigen::VectorXd& theta) {
  return effect_parameters(model, theta, model.effect);
}

EffectParameters effect_parameters(const EffectModel& model, const Eigen::VectorXd& all_theta,
                                   Effect effect) {
  const Eigen::VectorXd theta = slice_of(model, all_theta, effect);
  if (theta.size() != effect_parameter_count(effect)) return EffectParameters();
  return describe(effect).hooks.parameters(theta, model.nominal, model.impulse_time_s);
}

}  // namespace aloft::host::diagnose
