// diagnose/rest_periods: a log that lies still around a throw gives its noise back; a hand
// moving slowly is not rest; a flight cut from such a log carries the noise and its
// filter-settling time, and its noise floor says "rest".
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "diagnose/1_input/flight_input.hpp"
#include "diagnose/4_judge/noise_floor.hpp"
#include "diagnose/1_input/rest_periods.hpp"

using namespace aloft::host;
using namespace aloft::host::diagnose;

namespace {

// 200 Hz: `rest` s still (bias + noise), 1 s tumbling at ~10 rad/s, `rest` s still again.
ImuLog throw_between_rests(const Eigen::Vector3d& sigma, double rest, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  const Eigen::Vector3d bias(0.02, -0.01, 0.03);
  ImuLog log;
  const double end = 2.0 * rest + 1.0;
  for (int k = 0; k * 0.005 <= end; ++k) {
    const double t = 0.005 * k;
    Eigen::Vector3d w = bias;
    if (t >= rest && t <= rest + 1.0)
      w += Eigen::Vector3d(6.0 * std::cos(4.0 * t), 6.0 * std::sin(4.0 * t), 5.0);
    log.time_s.push_back(t);
    log.gyro_rad_s.push_back(
        w + Eigen::Vector3d(sigma(0) * unit(random), sigma(1) * unit(random), sigma(2) * unit(random)));
  }
  return log;
}

Body plain_body() { return parse_body_json(R"({"mass": 1, "inertia": {"principal": [1, 2, 3]}})", "test"); }

}  // namespace

TEST_CASE("rest periods around a throw give the noise per axis", "[rest]") {
  const Eigen::Vector3d sigma(0.004, 0.008, 0.016);
  const ImuLog log = throw_between_rests(sigma, 1.5, 5);
  const std::vector<RestPeriod> periods = find_rest_periods(log);
  REQUIRE(periods.size() == 2);
  CHECK(periods[0].still_until_s == Approx(1.5).margin(0.01));
  const auto noise = rest_noise(periods);
  REQUIRE(noise);
  CHECK(noise->periods == 2);
  for (int a = 0; a < 3; ++a) CHECK(noise->sigma(a) == Approx(sigma(a)).epsilon(0.1));
  CHECK(released_from_rest(periods, 1.5));
  CHECK(released_from_rest(periods, 1.7));  // after a spin-up in the hand
  CHECK_FALSE(released_from_rest(periods, 2.0));
}

TEST_CASE("too short a rest, or a slow motion below the still rate, is not rest", "[rest]") {
  CHECK(find_rest_periods(throw_between_rests(Eigen::Vector3d::Constant(0.01), 0.6, 7)).empty());
  // A hand holding the sensor: 0.2 rad/s swaying at 1 Hz, with little noise.
  ImuLog hand;
  for (int k = 0; k < 600; ++k) {
    const double t = 0.005 * k;
    hand.time_s.push_back(t);
    hand.gyro_rad_s.push_back(Eigen::Vector3d(0.2 * std::sin(6.3 * t), 0.1 * std::cos(6.3 * t), 0.0) +
                              Eigen::Vector3d::Constant(0.001 * ((k % 3) - 1)));
  }
  CHECK(find_rest_periods(hand).empty());
}

TEST_CASE("a flight cut from a log with rest takes its noise floor from the rest", "[rest][noise_floor]") {
  const Eigen::Vector3d sigma(0.01, 0.01, 0.01);
  const ImuLog log = throw_between_rests(sigma, 1.5, 9);
  const Flight flight = flight_from_imu(log, plain_body(), 1.5, 2.5, "throw");
  REQUIRE(flight.rest_noise);
  CHECK(flight.settling_until_s == Approx(1.5 + kFilterSettling_s));
  const NoiseFloor floor = estimate_noise_floor(flight);
  CHECK(std::string(floor.method) == "rest");
  CHECK(floor.sigma.mean() == Approx(0.01).epsilon(0.1));
  // The whole log cut without rest around it: no settling, still the rest's noise.
  const Flight whole = flight_from_imu(log, plain_body(), -INFINITY, INFINITY, "all");
  CHECK(std::isinf(whole.settling_until_s));
}
