// Rigid-body pose files of SPEC §3, read into PoseTrial (orientation body -> world,
// Hamilton, aloft/dynamics/rotation.hpp; position of the body origin in metres).
//
// OpenSim .mot / .sto: a header of key=value lines up to "endheader" (inDegrees=yes|no
// is required; nRows and nColumns, when given, are checked), then a row of column names
// and rows of numbers separated by tabs or spaces. The pose is a free joint whose
// columns are found by name only — OpenSim's names for a free joint, or the user's
// naming (--pose-columns, --osim/--joint): see free_joint.hpp. A file whose columns
// name no free joint is refused, listing its columns and how to name the pose; it is
// never read by column position. Without translation columns the trial has no positions.
//
// Pose CSV: header t,qw,qx,qy,qz with optional x,y,z (metres); other columns (for
// example the wx,wy,wz of `aloft simulate` and `aloft study` output) are ignored.
// A quaternion whose norm is off 1 by more than 1e-3 is an error; others are normalised.
//
// Both readers make consecutive quaternions lie in the same hemisphere (q and -q are
// the same rotation), so that differences and interpolation between samples are short.
// Errors are aloft::host::Error "FILE:LINE: problem".
#pragma once

#include <string>

#include "common/trial.hpp"
#include "readers/free_joint.hpp"

namespace aloft::host {

PoseTrial read_mot(const std::string& path, const PoseNaming& naming = {});  // .mot and .sto
PoseTrial read_pose_csv(const std::string& path);

}  // namespace aloft::host
