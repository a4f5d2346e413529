// The fixed list of flights for the withheld-effect test of `aloft diagnose` (issue 5):
// every effect of SPEC §4 several times, noise-only flights, every body of the
// catalogue, gyro and marker data. The list and its seeds never change, so the test's
// score is reproducible; the diagnosis must not look at a case's truth.
//
//   IMU (1 kHz gyro):      none × 6, each of the nine effects × 5          = 51 flights
//   markers (250 Hz TRC):  none × 4, each of the five body effects × 3     = 19 flights
// Bodies cycle through body_names() so each effect meets several bodies, except that
// internal_damping skips the near-symmetric cylinder, on which it loses < 0.5 % of the
// energy in a second (see flight_generator.hpp); every third IMU flight also carries
// an accelerometer (ax,ay,az columns).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "flight_generator.hpp"

namespace aloft::generator {

struct FlightCase {
  std::string name;  // e.g. "imu_gyro_bias_2": unique, usable as a folder name
  FlightSpec spec;
  std::uint64_t seed = 0;
};

std::vector<FlightCase> withheld_effect_cases();

}  // namespace aloft::generator
