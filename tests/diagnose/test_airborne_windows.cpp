// Flights found in a long log without --segments (issue 8 item 3, issue 31 item 4): the
// log runs through the firmware's release and landing code, as `aloft replay` runs it, so
// a spinning body whose accelerometer sits off its centre of mass is found too.
#include <catch2/catch.hpp>

#include <cmath>

#include "diagnose/1_input/airborne_windows.hpp"
#include "generated_throws.hpp"  // tests/host

using namespace aloft::host;
using namespace aloft::host::diagnose;

namespace {

// The generated recording as the IMU CSV a user gives diagnose (seconds, sensor axes).
ImuLog as_log(const aloft_test::Recording& recording) {
  ImuLog log;
  log.path = "generated.csv";
  log.format = "imu_csv";
  for (std::size_t i = 0; i < recording.samples.size(); ++i) {
    const auto& s = recording.samples[i];
    log.time_s.push_back(static_cast<double>(s.t_us) * 1e-6);
    log.gyro_rad_s.push_back(s.gyro_rad_s);
    log.accel_m_s2.push_back(s.accel_m_s2);
    log.line_numbers.push_back(i + 2);
  }
  log.header_line = 1;
  return log;
}

Body body_of(const aloft_test::Recording& recording, bool position_given) {
  Body body;
  body.name = "generated";
  body.mass_kg = 1.0;
  REQUIRE(aloft::InertiaTensor<double>::make_from_tensor(recording.nominal_tensor, body.inertia) ==
          aloft::Status::ok);
  body.imu_to_body = recording.sensor_to_body;
  if (position_given) body.imu_position_m = recording.imu_position_m;
  return body;
}

double truth_s(const aloft_test::Recording& recording, double t) {
  return t + static_cast<double>(recording.t0_us) * 1e-6;
}

}  // namespace

TEST_CASE("airborne windows: spinning throws by a real hand, found as the firmware finds them", "[session]") {
  // Seeds of the held-out set of the release tests (tests/host/test_release_detection.cpp),
  // at 1 kHz, with a real IMU's errors, the IMU 3–8 cm off the centre of mass.
  int throws = 0, found = 0;
  for (std::uint32_t seed = 2600; seed < 2606; ++seed) {
    aloft_test::RecordingSpec spec;
    spec.rate_hz = 1000;
    spec.throws = 3;
    spec.sensor_errors = true;
    spec.real_hand = true;
    spec.seed = seed;
    const aloft_test::Recording recording = aloft_test::ThrowGenerator(spec).generate();
    const ImuLog log = as_log(recording);
    for (bool given : {true, false}) {
      const std::vector<Segment> windows = airborne_windows(log, body_of(recording, given), "body.json");
      CAPTURE(seed, given, windows.size());
      for (const aloft_test::TrueFlight& truth : recording.flights) {
        if (truth.landing_s - truth.release_s < kShortestFlight_s) continue;
        ++throws;
        for (const Segment& w : windows) {
          const double early_s = truth_s(recording, truth.force_below_1_s) - w.start_s;
          const double late_s = w.start_s - truth_s(recording, truth.release_s);
          if (early_s <= 0.010 && late_s <= 0.020 &&
              std::abs(w.end_s - truth_s(recording, truth.landing_s)) <= 0.030) {
            ++found;
            CHECK(w.comment.find("firmware's release and landing code") != std::string::npos);
          }
        }
      }
    }
  }
  CAPTURE(throws, found);
  CHECK(throws >= 30);
  CHECK(found >= throws * 9 / 10);
}

TEST_CASE("airborne windows: none without an accelerometer", "[session]") {
  aloft_test::RecordingSpec spec;
  spec.seed = 2600;
  const aloft_test::Recording recording = aloft_test::ThrowGenerator(spec).generate();
  ImuLog log = as_log(recording);
  log.accel_m_s2.clear();
  CHECK(airborne_windows(log, body_of(recording, true), "body.json").empty());
}
