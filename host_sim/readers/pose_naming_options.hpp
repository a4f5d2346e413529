// The command-line options by which a user names the pose in a .mot/.sto file that does
// not name it itself (free_joint.hpp): --pose-columns, --pose-sequence, --osim, --joint.
// Registered by every command that reads pose files (inspect, study, diagnose).
#pragma once

#include <CLI/CLI.hpp>

#include "readers/free_joint.hpp"

namespace aloft::host {

void add_pose_naming_options(CLI::App& command, PoseNaming& naming);

}  // namespace aloft::host
