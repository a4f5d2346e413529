// The replay report as a table for the terminal: one line for the stream, then one row
// per flight (times in the recording's base, as in the JSON report).
#pragma once

#include <string>

#include "replay/recording.hpp"
#include "replay/replay_run.hpp"

namespace aloft::host {

std::string replay_report_text(const Recording& recording, const ReplayResult& result);

}  // namespace aloft::host
