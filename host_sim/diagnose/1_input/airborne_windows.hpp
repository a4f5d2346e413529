// The flights inside a long IMU log given without --segments or --window, found by the
// firmware's own release and landing code: the log runs through the onboard pipeline
// exactly as `aloft replay --imu` runs it (replay/replay_run.hpp), with the body file's
// `imu.position` or, without one, the pipeline's estimate of it. One implementation of
// "when does a flight start and end" serves the firmware, replay and diagnose, so a
// spinning body whose accelerometer sits off its centre of mass (|a| = |w x (w x r)|, far
// from free fall) is found as the firmware finds it.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "common/body_file.hpp"
#include "common/trial.hpp"

namespace aloft::host::diagnose {

// A log longer than this holds rest or several throws, not one flight: a throw lasts
// a second or two.
constexpr double kLongLog_s = 5.0;
// Shorter airborne runs are jolts, not throws.
constexpr double kShortestFlight_s = 0.2;

// One flight as the firmware's code found it, in the log's own time base.
struct FirmwareFlight {
  double release_s = 0.0;
  double landing_s = 0.0;  // the log's last sample when it ends in the air
  bool landed = false;
  Eigen::Vector3d imu_position_m = Eigen::Vector3d::Zero();  // body axes, as the firmware used it
  bool imu_position_estimated = false;
};

// Every flight the firmware's code finds in `log` (none without an accelerometer).
// Throws Error naming `body_source` or the log when the pipeline refuses the tensor or a
// sample.
std::vector<FirmwareFlight> firmware_flights(const ImuLog& log, const Body& body,
                                             const std::string& body_source);

// The airborne windows of `log` as segments "airborne1", "airborne2", ..., each from the
// pipeline's release to its landing (or to the log's end when the log ends in the air).
// Empty when the log has no accelerometer or no flight; throws as firmware_flights.
std::vector<Segment> airborne_windows(const ImuLog& log, const Body& body, const std::string& body_source);

}  // namespace aloft::host::diagnose
