// One flight out of a longer IMU log: the samples inside a time window (a segment of
// the segments file, or --window A:B).
#pragma once

#include <string>

#include "common/trial.hpp"

namespace aloft::host {

// The samples with start_s <= t <= end_s, gyro and accelerometer alike. `label` names
// the window in messages ("segment 3", "--window 1.2:2.0"). Throws aloft::host::Error
// "FILE: label (A–B s) holds N samples; the log spans C–D s" when fewer than two
// samples fall inside: no rate can be measured from that. Callers needing more samples
// to judge a flight check the size themselves.
ImuLog imu_window(const ImuLog& log, double start_s, double end_s, const std::string& label);

}  // namespace aloft::host
