// The segments file of SPEC §3: CSV `segment,start,end[,keep,comment]`, one flight per
// row inside a longer IMU log (times in seconds, as phyphox sessions are annotated).
// Cells may carry spaces. A row whose keep cell is false (also "no", "0") is not a
// flight and is skipped before its other cells are read (real exports leave its start
// and end blank); an empty keep cell means keep. A comment with unquoted commas
// is kept whole.
#pragma once

#include <string>
#include <vector>

#include "common/trial.hpp"

namespace aloft::host {

// The kept segments in file order. Throws aloft::host::Error "FILE:LINE: problem" for a
// wrong header, a missing or non-numeric start/end, end <= start, or an unknown keep
// value; and when no segment is kept.
std::vector<Segment> read_segments_csv(const std::string& path);

}  // namespace aloft::host
