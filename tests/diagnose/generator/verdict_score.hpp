// Scoring a diagnosis against a generated flight's truth, with the thresholds of
// issue 5, so that the withheld-effect test judges by rules written on the generator's
// side rather than the fitter's:
//   class     the verdict's effect is the truth's effect or in its equivalence class
//             (noise-only flights: the verdict must be "none");
//   params    gyro_bias: |b_fit - b| <= 20 % of |b|;
//             gyro_scale: every |s_fit,i - s_i| <= 0.01 (a clock drift eps read as
//               gyro_scale: every |s_fit,i - eps| <= 0.01);
//             clock_drift: |eps_fit - eps| <= 0.01 (the scale tolerance: they are one);
//             inertia_axes, sensor_misalignment (either for the other, from a gyro):
//               |angle_fit - angle| <= 2°;
//             aero_torque: |k_fit - k| <= 25 % of k;
//             impulse: |time_fit - time| <= 30 ms;
//             none, inertia_moments, internal_damping: no parameter threshold.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "flight_generator.hpp"

namespace aloft::generator {

struct VerdictScore {
  bool class_right = false;     // see above
  bool params_checked = false;  // a parameter threshold applied (class right and one exists)
  bool params_right = false;    // within the threshold, or no threshold and class right
  std::string detail;           // one line: what was compared, for a failing test's message
};

// `verdict` is the "verdict" object of the SPEC §4 report: {"effect", "params", ...}.
VerdictScore score_verdict(const FlightTruth& truth, const nlohmann::json& verdict);

}  // namespace aloft::generator
