// The built-in trial as the study sees it: the synthetic throw's markers
// (study/synthetic_throw.hpp) turned into poses by the same rigid fit a recording gets
// (readers/marker_pose_fit.hpp), resampled from 250 Hz to 1 kHz with the tangent-space
// spline (study/tangent_spline_resampler.hpp): 873 samples over 0.872 s, as in the paper.
#pragma once

#include <nlohmann/json.hpp>

#include "study/study_flight.hpp"
#include "study/synthetic_throw.hpp"

namespace aloft::host {

struct BuiltInTrial {
  Body body;
  StudyFlight flight;
  nlohmann::json description;  // every choice, for results.json
};

BuiltInTrial make_built_in_trial(const SyntheticThrowSettings& settings = {});

// The paper's compound pendulum tensor: its principal moments along the CCS axes.
InertiaTensor<double> compound_pendulum_inertia();

}  // namespace aloft::host
