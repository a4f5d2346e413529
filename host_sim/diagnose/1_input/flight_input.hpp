// Flights from the trial data model (common/trial.hpp): an IMU log as one flight, a
// window of it, or the segments of a session; or the body rates of a pose trial.
#pragma once

#include <string>
#include <vector>

#include "common/body_file.hpp"
#include "common/trial.hpp"
#include "diagnose/1_input/flight.hpp"

namespace aloft::host::diagnose {

// The samples of `log` with from_s <= t <= to_s, in sensor axes, saturated samples marked.
// When the log has rest periods (rest_periods.hpp), the flight carries the noise measured
// there; when it was released from rest, it says until when its gyro's filter settles.
Flight flight_from_imu(const ImuLog& log, const Body& body, double from_s, double to_s,
                       const std::string& name);

std::vector<Flight> flights_from_segments(const ImuLog& log, const Body& body,
                                          const std::vector<Segment>& segments);

// Segments the user gave (--segments, --window): each cut to its flight where the
// accelerometer shows a hand or the ground inside it (contact.hpp), the cut named in
// Flight::contacts. Without an accelerometer, flights_from_segments.
std::vector<Flight> flights_from_given_segments(const ImuLog& log, const Body& body,
                                                const std::string& body_source,
                                                const std::vector<Segment>& segments);

// Body rates log(R_k^-1 R_k+1)/dt of consecutive poses at the midpoint of each pair, body
// axes (readers/body_rates.hpp; pairs across a gap are skipped). No sensor: sensor
// effects do not apply.
Flight flight_from_poses(const PoseTrial& poses, const std::string& name);

}  // namespace aloft::host::diagnose
