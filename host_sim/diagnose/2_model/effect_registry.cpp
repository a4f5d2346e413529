// The registry: every effect of effects/effect_list.def, indexed by its enum value, and
// the common questions answered from the descriptors.
#include "diagnose/2_model/effect.hpp"

#include <array>
#include <cstddef>

#include "diagnose/2_model/effect_descriptor.hpp"

namespace aloft::host::diagnose {
namespace {

constexpr std::array kRegistry = {
#define ALOFT_EFFECT(name) &name##_effect,
#include "diagnose/2_model/effects/effect_list.def"
#undef ALOFT_EFFECT
};

}  // namespace

const EffectDescriptor& describe(Effect effect) { return *kRegistry[static_cast<std::size_t>(effect)]; }

std::vector<Effect> registered_effects() {
  std::vector<Effect> all;
  for (std::size_t i = 0; i < kRegistry.size(); ++i) all.push_back(static_cast<Effect>(i));
  return all;
}

std::string no_objection(const EffectParameters&) { return {}; }
std::string no_physics_objection(const FittedSlice&) { return {}; }

const char* effect_name(Effect effect) { return describe(effect).name; }

int effect_parameter_count(Effect effect) { return describe(effect).parameter_count; }

int effect_penalty_count(Effect effect) {
  return describe(effect).parameter_count + describe(effect).searched_parameters;
}

bool is_sensor_effect(Effect effect) { return describe(effect).sensor; }

std::vector<Effect> candidate_effects(bool gyro_input) {
  std::vector<Effect> out;
  for (Effect e : registered_effects()) {
    if (describe(e).variant_of != Effect::none) continue;  // tried by variant_candidates.hpp
    if (gyro_input || !is_sensor_effect(e)) out.push_back(e);
  }
  return out;
}

std::vector<Effect> always_equivalent(Effect effect, bool gyro_input) {
  std::vector<Effect> out{effect};
  if (!gyro_input) return out;
  for (Effect e : describe(effect).gyro_equivalents) {
    if (e != Effect::none) out.push_back(e);
  }
  return out;
}

}  // namespace aloft::host::diagnose
