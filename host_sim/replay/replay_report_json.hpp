// The replay report of SPEC §5 as JSON:
//   { "recording": {...}, "stream": { "samples", "invalid_samples", "clipped_samples",
//                 "bytes_skipped", "empty_reads", "resyncs", "gaps": [ { "at_s", "length_s" } ],
//                 "lost_s" },
//     "flights": [ { "flight", "release_s", "landing_s", "samples", "gaps",
//                    "clipped_samples", "imu_position_m", "imu_position_from",
//                    "rms_da_deg", "max_da_deg", "rms_rel_err", "comparisons"[, "note"] } ] }
// Times in the recording's own base (the CSV's `t`), exact to the microsecond. A gap's
// at_s is the last sample before the hole and length_s the step to the next sample.
// landing_s is null when the flight did not land (the recording ended or broke off while
// airborne). rms_da_deg, max_da_deg and rms_rel_err are null, with a `note`, when the
// flight turned too little to say anything about the tensor, or made no comparison.
#pragma once

#include <nlohmann/json.hpp>

#include "replay/recording.hpp"
#include "replay/replay_run.hpp"

namespace aloft::host {

nlohmann::json replay_report_json(const Recording& recording, const ReplayResult& result);

}  // namespace aloft::host
