// OpenSim/Vicon marker trajectories (.trc), tab separated:
//   line 1  PathFileType  4  (X/Y/Z)  name
//   line 2  DataRate CameraRate NumFrames NumMarkers Units [OrigDataRate ...]
//   line 3  their values
//   line 4  Frame#  Time  M1 <tab> <tab> M2 ...        (one name per X/Y/Z triplet)
//   line 5  <tab> <tab> X1 Y1 Z1 X2 ...
//   then one row per frame (blank lines skipped): frame number, time, coordinates.
// Units mm, cm or m are converted to metres. A triplet left empty (or NaN) is an
// occluded marker and becomes NaN; a triplet with only some coordinates is an error.
// The row count must equal NumFrames, so a truncated file is caught. Errors are
// aloft::host::Error "FILE:LINE: problem".
#pragma once

#include <string>

#include "common/trial.hpp"

namespace aloft::host {

MarkerTrial read_trc(const std::string& path);

// Metres per unit for a unit name as marker files state it ("mm", "cm", "m",
// case-insensitive); 0 for an unknown unit.
double metres_per_unit(const std::string& unit);

}  // namespace aloft::host
