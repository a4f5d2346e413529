// A recording as the study sees it (`aloft study --body B.json --markers|--poses|--imu`):
//  - markers (.trc, .c3d): the body's marker set fitted to each frame (frames with fewer
//    than three visible markers are dropped by the fit), the poses resampled to 1 kHz
//    with the tangent-space spline, like the built-in throw. Gaps left by dropped frames
//    are bridged by the spline and listed in the description, not hidden;
//  - poses (.mot, .sto, pose .csv): resampled to 1 kHz the same way;
//  - IMU (plain or phyphox .csv): a rate flight per segment of --segments (or the whole
//    log without it), the gyro rotated into body axes by the body's imu rotation and
//    compared at its own samples; no orientation is needed.
// Errors are aloft::host::Error with one line naming the file and the problem.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "common/body_file.hpp"
#include "readers/free_joint.hpp"
#include "readers/imu_units.hpp"
#include "study/study_flight.hpp"

namespace aloft::host {

struct RecordingInput {
  std::string body_path;
  std::string body_json;  // the body's content when handed over in memory (body_path names it)
  std::string markers_path;
  std::string poses_path;
  std::string imu_path;
  std::string segments_path;
  PoseNaming pose_naming;  // --pose-columns / --osim --joint for a .mot/.sto
  ImuUnits imu_units;      // --time-units, --gyro-units, --accel-units for an IMU log
};

struct RecordedTrial {
  Body body;
  std::vector<StudyFlight> flights;
  nlohmann::json description;
};

RecordedTrial load_recorded_trial(const RecordingInput& input);

// The time gaps (readers/time_stamps.hpp's rule) as JSON intervals.
nlohmann::json time_gaps(const std::vector<double>& time_s);

}  // namespace aloft::host
