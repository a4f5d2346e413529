// The unmodelled effects `aloft diagnose` considers (SPEC §4). Each is described in one
// place, its descriptor (effect_descriptor.hpp, effects/<name>.cpp); the enum below is
// made from the registry list (effects/effect_list.def), so adding an effect adds no case
// here. The functions below are the questions the rest of diagnose asks most often.
#pragma once

#include <vector>

namespace aloft::host::diagnose {

enum class Effect {
#define ALOFT_EFFECT(name) name,
#include "diagnose/2_model/effects/effect_list.def"
#undef ALOFT_EFFECT
};

const char* effect_name(Effect effect);

// Free parameters the effect adds to the flight's initial state (the impulse time is
// searched on a grid, not counted here, but it is counted in the ranking penalty).
int effect_parameter_count(Effect effect);

// Parameters the ranking charges the effect for (impulse: its time as well).
int effect_penalty_count(Effect effect);

// Gyro bias, scale, misalignment and clock drift describe the sensor, not the motion.
bool is_sensor_effect(Effect effect);

// The candidate effects for IMU input (every registered effect) or motion capture (no sensor effects), in
// registry order.
std::vector<Effect> candidate_effects(bool gyro_input);

// Effects that gyro data cannot tell apart from `effect` whatever the flight, including
// `effect` itself first (each descriptor lists its own; SPEC §4 names two classes).
std::vector<Effect> always_equivalent(Effect effect, bool gyro_input);

}  // namespace aloft::host::diagnose
