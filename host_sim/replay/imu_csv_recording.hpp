// The plain IMU log of SPEC §3 (t,gx,gy,gz,ax,ay,az[,rotor_rad_s]; s, rad/s, m/s², rad/s;
// the rotor's speed in every sample, flagged imu_rotor_speed, where the log has it) as a Recording for
// `aloft replay --imu`: the samples in float, as the firmware's pipeline takes them, with
// t_us counted from the first sample (Recording::t0_s keeps the CSV's own first t, so
// reports give times in the CSV's base). The accelerometer columns are required: release
// and landing are told from them. A step longer than kGapFactor times the median step
// (readers/time_stamps.hpp, the one rule of every command) flags imu_gap_before. A CSV
// says nothing about clipping, so no sample is flagged clipped.
#pragma once

#include <string>

#include "common/trial.hpp"
#include "replay/recording.hpp"

namespace aloft::host {

// Throws aloft::host::Error "FILE:LINE: problem" for a file without accelerometer
// columns, a cell that is not a finite number, time not strictly increasing (also after
// rounding to whole microseconds), or a file without samples.
Recording read_imu_csv_recording(const std::string& path);

// The same from a log already read (and converted to SI units by the caller).
Recording imu_csv_recording(const ImuLog& log);

}  // namespace aloft::host
