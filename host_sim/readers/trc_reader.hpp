// OpenSim/Vicon marker trajectories (.trc), tab separated:
//   line 1  PathFileType  4  (X/Y/Z)  name
//   line 2  DataRate CameraRate NumFrames NumMarkers Units [OrigDataRate ...]
//   line 3  their values
//   line 4  Frame#  Time  M1 <tab> <tab> M2 ...        (one name per X/Y/Z triplet)
//   line 5  <tab> <tab> X1 Y1 Z1 X2 ...
//   then one row per frame (blank lines skipped): frame number, time, coordinates.
// Units mm, cm or m are converted to metres. A triplet left empty (or NaN) is an
// occluded marker and becomes NaN; a triplet with only some coordinates is an error.
// Empty header cells (repeated tabs) are dropped, as OpenSim's reader does. The rows
// present are read when NumFrames claims another count, with a warning giving both; a
// row cut short is an error. Errors are aloft::host::Error "FILE:LINE: problem".
#pragma once

#include <string>

#include "common/trial.hpp"

namespace aloft::host {

MarkerTrial read_trc(const std::string& path);

}  // namespace aloft::host
