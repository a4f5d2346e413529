// IMU logs of SPEC §3: CSV with a header row, in one of two layouts recognised by the
// header (column order free, names case-insensitive):
//   plain:   t, gx, gy, gz [, ax, ay, az] [, rotor_rad_s]   (s, rad/s, m/s², rad/s)
//   phyphox: "Time (s)", "Gyroscope x (rad/s)", "Gyroscope y (rad/s)",
//            "Gyroscope z (rad/s)" [, "Absolute (rad/s)"]   (the magnitude is ignored)
// Cells are delimited by commas, or, where the header holds none, by semicolons or tabs
// (then numbers may carry a decimal comma: phyphox's other exports); a UTF-8 byte order
// mark is dropped. Every sample must be finite and time strictly increasing; otherwise
// aloft::host::Error "FILE:LINE: problem".
#pragma once

#include <string>

#include "common/trial.hpp"

namespace aloft::host {

ImuLog read_imu_csv(const std::string& path);

}  // namespace aloft::host
