// Sanity of marker input (issue 8): when the body's marker set does not fit the trial
// (the pose fit's mean residual far above marker noise, which is well under 1 mm for
// motion capture), the poses, and every rate differenced from them, are wrong, and a
// verdict of `none` would be a lie. `aloft diagnose --markers` refuses such a trial with
// a one-line reason.
#pragma once

#include <optional>
#include <string>

#include "readers/marker_pose_fit.hpp"

namespace aloft::host::diagnose {

// "Several mm": an order of magnitude above the 0.27-0.29 mm of the practice trials.
constexpr double kLargestMarkerResidual_m = 0.003;

// The reason to refuse, or nothing when the markers fit (report: fit_poses of trial and
// body). The reason names the markers without which the rest fit (misplaced or
// mislabelled ones), or says that none stands out (a wrong scale or units).
std::optional<std::string> marker_misfit(const MarkerTrial& trial, const Body& body,
                                         const PoseFitReport& report);

}  // namespace aloft::host::diagnose
