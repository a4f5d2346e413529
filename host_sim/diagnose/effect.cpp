#include "diagnose/effect.hpp"

namespace aloft::host::diagnose {

const char* effect_name(Effect effect) {
  switch (effect) {
    case Effect::none: return "none";
    case Effect::inertia_moments: return "inertia_moments";
    case Effect::inertia_axes: return "inertia_axes";
    case Effect::aero_torque: return "aero_torque";
    case Effect::internal_damping: return "internal_damping";
    case Effect::impulse: return "impulse";
    case Effect::gyro_bias: return "gyro_bias";
    case Effect::gyro_scale: return "gyro_scale";
    case Effect::sensor_misalignment: return "sensor_misalignment";
    case Effect::clock_drift: return "clock_drift";
  }
  return "none";
}

int effect_parameter_count(Effect effect) {
  switch (effect) {
    case Effect::none: return 0;
    case Effect::inertia_moments: return 2;
    case Effect::inertia_axes: return 3;
    case Effect::aero_torque: return 1;
    case Effect::internal_damping: return 2;
    case Effect::impulse: return 3;
    case Effect::gyro_bias: return 3;
    case Effect::gyro_scale: return 3;
    case Effect::sensor_misalignment: return 3;
    case Effect::clock_drift: return 1;
  }
  return 0;
}

int effect_penalty_count(Effect effect) {
  return effect_parameter_count(effect) + (effect == Effect::impulse ? 1 : 0);
}

bool is_sensor_effect(Effect effect) {
  return effect == Effect::gyro_bias || effect == Effect::gyro_scale ||
         effect == Effect::sensor_misalignment || effect == Effect::clock_drift;
}

std::vector<Effect> candidate_effects(bool gyro_input) {
  std::vector<Effect> all = {Effect::none,         Effect::inertia_moments,
                             Effect::inertia_axes, Effect::aero_torque,
                             Effect::internal_damping, Effect::impulse,
                             Effect::gyro_bias,    Effect::gyro_scale,
                             Effect::sensor_misalignment, Effect::clock_drift};
  if (gyro_input) return all;
  std::vector<Effect> motion;
  for (Effect e : all) {
    if (!is_sensor_effect(e)) motion.push_back(e);
  }
  return motion;
}

std::vector<Effect> always_equivalent(Effect effect, bool gyro_input) {
  if (gyro_input) {
    if (effect == Effect::inertia_axes || effect == Effect::sensor_misalignment) {
      return {effect, effect == Effect::inertia_axes ? Effect::sensor_misalignment
                                                     : Effect::inertia_axes};
    }
    if (effect == Effect::clock_drift) return {Effect::clock_drift, Effect::gyro_scale};
  }
  return {effect};
}

}  // namespace aloft::host::diagnose
