// A segments file checked against the log it cuts, before any flight is diagnosed: a
// segment that does not lie inside the log, or that covers a rest period, is bad input
// (once, segments in ms ran to verdict `none` with exit 0).
#pragma once

#include <string>
#include <vector>

#include "common/trial.hpp"

namespace aloft::host::diagnose {

// Throws aloft::host::Error, one line naming the segment and `segments_path`, for the
// first segment that starts before the log's first sample or ends after its last (with
// a word when the segments would fit the log in ms), that holds too few samples (with a
// word when the log's clock looks like ms), or over which the body lies still.
void check_segments(const ImuLog& log, const std::vector<Segment>& segments,
                    const std::string& segments_path);

}  // namespace aloft::host::diagnose
