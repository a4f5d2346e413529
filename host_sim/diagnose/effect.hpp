// The unmodelled effects `aloft diagnose` considers (SPEC §4): their fixed names, how
// many free parameters each adds to the torque-free model, which apply to IMU input
// only, and which the data of a gyro alone cannot tell apart.
#pragma once

#include <string>
#include <vector>

namespace aloft::host::diagnose {

enum class Effect {
  none,                 // measurement noise only
  inertia_moments,      // principal moments wrong (ratios; the scale is free)
  inertia_axes,         // principal axes rotated from nominal
  aero_torque,          // tau = -k |w| w
  internal_damping,     // a spherical rotor in a viscous cavity: energy loss at constant |L|
  impulse,              // an instantaneous angular impulse at one time
  gyro_bias,            // measured = true + b
  gyro_scale,           // measured_i = (1 + s_i) true_i
  sensor_misalignment,  // sensor axes rotated from body axes
  clock_drift,          // recorded time = true time * (1 + eps)
};

const char* effect_name(Effect effect);

// Free parameters the effect adds to the flight's initial state (the impulse time is
// searched on a grid, not counted here, but it is counted in the ranking penalty).
int effect_parameter_count(Effect effect);

// Parameters the ranking charges the effect for (impulse: its time as well).
int effect_penalty_count(Effect effect);

// Gyro bias, scale, misalignment and clock drift describe the sensor, not the motion.
bool is_sensor_effect(Effect effect);

// The candidate effects for IMU input (every effect) or motion capture (no sensor effects).
std::vector<Effect> candidate_effects(bool gyro_input);

// Effects that gyro data cannot tell apart from `effect` whatever the flight, including
// `effect` itself: inertia_axes == sensor_misalignment (a rotated tensor and a rotated
// sensor give the same readings), clock_drift == a uniform gyro_scale (a torque-free
// motion sped up by (1+eps) is the same motion with every rate scaled by (1+eps)).
std::vector<Effect> always_equivalent(Effect effect, bool gyro_input);

}  // namespace aloft::host::diagnose
