// The units an IMU log may be written in besides aloft's own (s, rad/s, m/s²), named by
// the user with --time-units, --gyro-units and --accel-units and converted right after
// the log is read, so that nothing downstream sees anything but SI. A log's units are
// not guessed from the size of its numbers (a ball really spins at 200 rad/s); the
// diagnosis checks them against the physics and names these options when they are off
// (readers/rate_units_check.hpp).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "common/trial.hpp"

namespace aloft::host {

struct ImuUnits {
  std::string time = "s";      // s, ms, us
  std::string gyro = "rad/s";  // rad/s, deg/s
  std::string accel = "m/s2";  // m/s2, g
};

// Standard gravity (m/s²): what an accelerometer in g is multiplied by.
constexpr double kStandardGravity_m_s2 = 9.80665;

// --time-units, --gyro-units, --accel-units on `command`.
void add_imu_unit_options(CLI::App& command, ImuUnits& units);

// Converts the log's times, rates and accelerations to s, rad/s and m/s².
void convert_to_si(ImuLog& log, const ImuUnits& units);

}  // namespace aloft::host
