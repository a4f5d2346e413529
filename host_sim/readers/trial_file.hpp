// Which of the trial formats of SPEC §3 a file holds, told by its extension and then by
// its content, and readers that dispatch on it. Used by `aloft inspect` and by the
// commands that take --markers / --poses.
#pragma once

#include <string>

#include "common/trial.hpp"
#include "readers/free_joint.hpp"

namespace aloft::host {

enum class TrialKind { markers, poses, imu, segments };

struct TrialFormat {
  TrialKind kind = TrialKind::markers;
  // "trc", "c3d", "mot", "sto", "pose_csv", "imu_csv", "phyphox" or "segments".
  std::string name;
};

// Extensions .trc, .c3d, .mot and .sto decide; otherwise the content does: a C3D header,
// a TRC first line, an OpenSim "endheader", or the CSV header row. Throws
// aloft::host::Error when the file cannot be opened or matches no format.
TrialFormat detect_trial_format(const std::string& path);

// A marker file (.trc or .c3d); throws if the file holds another kind of trial.
MarkerTrial read_marker_file(const std::string& path);

// A pose file (.mot, .sto or pose CSV); throws if the file holds another kind of trial.
// `naming` names the pose of a .mot/.sto (free_joint.hpp); a pose CSV takes none.
PoseTrial read_pose_file(const std::string& path, const PoseNaming& naming = {});

}  // namespace aloft::host
