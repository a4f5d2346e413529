// Flights found in a long log without --segments (issue 8 item 3, issue 31 item 4): the
// log runs through the firmware's release and landing code, as `aloft replay` runs it, so
// a spinning body whose accelerometer sits off its centre of mass is found too.
#include <catch2/catch.hpp>

#include <cmath>

#include "diagnose/1_input/airborne_windows.hpp"
#include "diagnose/1_input/contact.hpp"
#include "diagnose/1_input/flight_input.hpp"
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

// Three throws by a real hand at 1 kHz, with a real IMU's errors.
aloft_test::Recording real_hand_throws(std::uint32_t seed) {
  aloft_test::RecordingSpec spec;
  spec.rate_hz = 1000;
  spec.throws = 3;
  spec.sensor_errors = true;
  spec.real_hand = true;
  spec.seed = seed;
  return aloft_test::ThrowGenerator(spec).generate();
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
    const aloft_test::Recording recording = real_hand_throws(seed);
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

TEST_CASE("given segments: the hand and the catch inside them are cut away and named", "[session]") {
  // Segments drawn generously, as by hand: from 80 ms before the release to 60 ms after the
  // landing. The hand's push and the catch are tens of m/s^2 beyond rotation.
  int segments = 0, cut_at_release = 0, cut_at_landing = 0;
  for (std::uint32_t seed = 2600; seed < 2604; ++seed) {
    const aloft_test::Recording recording = real_hand_throws(seed);
    const ImuLog log = as_log(recording);
    std::vector<Segment> given;
    std::vector<aloft_test::TrueFlight> truths;
    for (const aloft_test::TrueFlight& truth : recording.flights) {
      if (truth.landing_s - truth.release_s < 0.3 || truth.release_rate_rad_s < 5.0) continue;
      truths.push_back(truth);
      given.push_back({"throw", truth_s(recording, truth.release_s) - 0.080,
                       truth_s(recording, truth.landing_s) + 0.060, ""});
    }
    const std::vector<Flight> flights =
        flights_from_given_segments(log, body_of(recording, true), "body.json", given);
    REQUIRE(flights.size() == given.size());
    for (std::size_t i = 0; i < flights.size(); ++i) {
      ++segments;
      const aloft_test::TrueFlight& truth = truths[i];
      for (const Contact& c : flights[i].contacts) {
        CAPTURE(seed, i, c.beyond_rotation_m_s2, c.cut_from_s, c.cut_to_s);
        CHECK(c.beyond_rotation_m_s2 >= kContactForce_m_s2);
        CHECK(c.at_s >= c.cut_from_s);
        CHECK(c.at_s <= c.cut_to_s);
        if (c.before_release) {
          ++cut_at_release;
          CHECK(flights[i].start_s() >= truth_s(recording, truth.force_below_1_s) - 0.010);
          CHECK(flights[i].start_s() <= truth_s(recording, truth.release_s) + 0.020);
        } else {
          ++cut_at_landing;
          CHECK(flights[i].end_s() <= truth_s(recording, truth.landing_s) + 0.005);
        }
      }
    }
  }
  CAPTURE(segments, cut_at_release, cut_at_landing);
  CHECK(segments >= 8);
  CHECK(cut_at_release >= segments * 9 / 10);
  CHECK(cut_at_landing >= segments * 9 / 10);
}

TEST_CASE("given segments: a segment inside the flight is left as it is", "[session]") {
  aloft_test::RecordingSpec spec;
  spec.real_hand = true;
  spec.seed = 2600;
  const aloft_test::Recording recording = aloft_test::ThrowGenerator(spec).generate();
  const aloft_test::TrueFlight& truth = recording.flights.front();
  const Segment inside{"inside", truth_s(recording, truth.release_s) + 0.030,
                       truth_s(recording, truth.landing_s) - 0.030, ""};
  const std::vector<Flight> flights =
      flights_from_given_segments(as_log(recording), body_of(recording, true), "body.json", {inside});
  REQUIRE(flights.size() == 1);
  CHECK(flights[0].contacts.empty());
  CHECK(flights[0].start_s() == Approx(inside.start_s).margin(0.0011));
  CHECK(flights[0].end_s() == Approx(inside.end_s).margin(0.0011));
}
