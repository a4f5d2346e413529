// A body file's moments checked against its mass and size: a tensor written in g·cm²
// (10^7 times kg·m²) once passed as 1.517e+04 kg·m² for a 1 kg box. Torque-free motion
// fixes only the ratios of the moments, so the diagnosis itself is unaffected, but every
// moment, torque and impulse it reports is then in the file's unit; hence a warning that
// names the likely unit rather than a refusal.
//
// The check is the radius of gyration k = sqrt(I_max / m) of the largest moment: no mass
// lies further from the centre of mass than the body's extent, so k is at most the
// farthest marker's distance (with room for mass beyond the markers: twice it) and, for
// a body one can throw, at most a few metres (a 2.7 m javelin has k ≈ 0.8 m).
#pragma once

#include <optional>
#include <string>

#include "common/body_file.hpp"

namespace aloft::host {

// Largest radius of gyration (m) of a body without markers that aloft takes as given.
constexpr double kLargestRadiusOfGyration_m = 3.0;

// The warning for a body whose moments do not fit its mass and size, naming the unit
// they are likely in; nothing when they fit, or when the file gives no mass.
std::optional<std::string> inertia_scale_problem(const Body& body);

}  // namespace aloft::host
