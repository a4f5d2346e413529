// One long IMU log of many throws of the same body (issue 12 item 7: a 10-minute 1 kHz
// log with 200 segments), for timing `aloft diagnose --segments` end to end. The throws
// are generate_flight's (flight_generator.hpp), laid one after another on one 1 kHz
// clock with rest between them: the body held still, the gyro reading its white noise.
// segments lists each throw's window.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "flight_generator.hpp"

namespace aloft::generator {

struct LongSessionSpec {
  std::string body = "box";
  std::string effect = "aero_torque";  // every throw's, each with its own drawn magnitude
  int flights = 200;
  double flight_s = 1.0;  // each throw's duration
  double rest_s = 2.0;    // before each throw (200 x (2 + 1) s = 10 minutes)
};

struct LongSessionLog {
  host::Body body;
  std::string body_json;  // SPEC §2, the nominal body
  host::ImuLog log;
  std::vector<host::Segment> segments;
};

// Deterministic in (spec, seed): throw i is generate_flight(..., seed + i).
LongSessionLog make_long_session_log(const LongSessionSpec& spec, std::uint64_t seed);

// Writes body.json, imu.csv and segments.csv (SPEC §3) into `dir` (created if needed).
void write_long_session_log(const LongSessionLog& session, const std::string& dir);

}  // namespace aloft::generator
