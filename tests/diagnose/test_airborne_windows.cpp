// Flights found in a long log without --segments (issue 8 item 3): the accelerometer's
// free fall marks each flight; a catch or a landing spike ends it.
#include <catch2/catch.hpp>

#include "diagnose/1_input/airborne_windows.hpp"

using namespace aloft::host;
using namespace aloft::host::diagnose;

namespace {

// 100 Hz: rest at 1 g, then for each (from, to) free fall (a centripetal 0.4 m/s^2),
// a catch (|a| back to about 1 g) or, for `spike`, a landing of 60 m/s^2.
ImuLog log_with_flights(const std::vector<std::pair<double, double>>& flights, bool spike) {
  ImuLog log;
  for (int k = 0; k < 1500; ++k) {
    const double t = 0.01 * k;
    double a = 9.81;
    for (const auto& [from, to] : flights) {
      if (t >= from && t < to) a = 0.4;
      if (spike && t >= to && t < to + 0.02) a = 60.0;
    }
    log.time_s.push_back(t);
    log.gyro_rad_s.push_back(Eigen::Vector3d::Zero());
    log.accel_m_s2.push_back(Eigen::Vector3d(0.0, 0.0, a));
  }
  return log;
}

}  // namespace

TEST_CASE("airborne windows: each free fall, ended by a catch or a landing", "[session]") {
  for (bool spike : {false, true}) {
    const std::vector<Segment> w =
        airborne_windows(log_with_flights({{2.0, 3.0}, {6.5, 7.4}, {10.0, 10.1}}, spike));
    REQUIRE(w.size() == 2);  // the 0.1 s jolt is no throw
    CHECK(w[0].start_s == Approx(2.0).margin(0.011));
    CHECK(w[0].end_s == Approx(2.99).margin(0.011));
    CHECK(w[1].start_s == Approx(6.5).margin(0.011));
    CHECK(w[1].end_s == Approx(7.39).margin(0.011));
  }
}

TEST_CASE("airborne windows: none without an accelerometer", "[session]") {
  ImuLog log = log_with_flights({{2.0, 3.0}}, false);
  log.accel_m_s2.clear();
  CHECK(airborne_windows(log).empty());
}
