// The fixed list of compound flights for the withheld-effect test (issue 8): two effects
// at once, one flight for every pair of different equivalence classes of SPEC §4 on
// gyro data (a representative of each class: inertia_moments, inertia_axes,
// aero_torque, internal_damping, impulse, gyro_bias, gyro_scale; 21 pairs). Bodies cycle
// through those with three distinct moments or a flat disc, never the near-symmetric
// cylinder (damping barely shows on it); wrong moments with a gyro scale fly the tilted
// box, whose principal axes are not its sensor axes (elsewhere a scale can mimic moments).
// Seeds and list never change.
#pragma once

#include <vector>

#include "withheld_effect_cases.hpp"

namespace aloft::generator {

std::vector<FlightCase> compound_effect_cases();

}  // namespace aloft::generator
