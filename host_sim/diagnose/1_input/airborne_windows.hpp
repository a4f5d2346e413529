// The flights inside a long IMU log given without --segments or --window, found with the
// core's flight detector (aloft/flight_detector.hpp) on the accelerometer: release is a
// run of free-fall samples, the end a landing spike or the hand's catch (|a| back above
// the free-fall threshold for as many samples as release needs).
#pragma once

#include <vector>

#include "common/trial.hpp"

namespace aloft::host::diagnose {

// A log longer than this holds rest or several throws, not one flight: a throw lasts
// a second or two.
constexpr double kLongLog_s = 5.0;
// Shorter airborne runs are jolts, not throws.
constexpr double kShortestFlight_s = 0.2;

// The airborne windows of `log` as segments "airborne1", "airborne2", ... (empty when the
// log has no accelerometer or no flight).
std::vector<Segment> airborne_windows(const ImuLog& log);

}  // namespace aloft::host::diagnose
