// diagnose/saturation: flat tops of a saturated gyro are left out, nothing else is.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "diagnose/1_input/saturation.hpp"

using namespace aloft::host::diagnose;

namespace {

// A noisy rate whose x axis swings to +-10 rad/s; clipped at `full_scale` when given.
Flight swinging_flight(double full_scale) {
  std::mt19937 random(2);
  std::normal_distribution<double> noise(0.0, 0.01);
  Flight f;
  for (int k = 0; k < 1000; ++k) {
    const double t = 0.001 * k;
    // Little noise on x, so that the clipped runs have clean edges.
    double x = 10.0 * std::sin(2.0 * M_PI * 2.0 * t) + 0.1 * noise(random);
    if (full_scale > 0.0) x = std::clamp(x, -full_scale, full_scale);
    f.time_s.push_back(t);
    f.omega.push_back(Eigen::Vector3d(x, 1.0 + noise(random), -2.0 + noise(random)));
    f.usable.push_back(1);
  }
  return f;
}

}  // namespace

TEST_CASE("mark_saturated_samples marks the flat tops and only them", "[saturation]") {
  Flight clipped = swinging_flight(9.5);
  std::size_t at_full_scale = 0;
  for (const Eigen::Vector3d& w : clipped.omega) at_full_scale += std::abs(w.x()) == 9.5;
  REQUIRE(at_full_scale > 20);
  const Saturation s = mark_saturated_samples(clipped);
  CHECK(s.samples == at_full_scale);
  CHECK(s.level_rad_s == Approx(9.5));
  for (std::size_t k = 0; k < clipped.size(); ++k) {
    CHECK(bool(clipped.usable[k]) == (std::abs(clipped.omega[k].x()) != 9.5));
  }
}

TEST_CASE("mark_saturated_samples leaves an unclipped flight and short repeats alone", "[saturation]") {
  Flight free = swinging_flight(0.0);
  CHECK(mark_saturated_samples(free).samples == 0);
  // Two equal readings at the peak are a coincidence of rounding, not a flat top.
  Flight twice = swinging_flight(0.0);
  twice.omega[126].x() = twice.omega[125].x();
  CHECK(mark_saturated_samples(twice).samples == 0);
  CHECK(std::all_of(twice.usable.begin(), twice.usable.end(), [](char c) { return c == 1; }));
}

TEST_CASE("mark_saturated_samples leaves a flight controller's finely quantised peaks alone",
          "[saturation]") {
  // 8 kHz, quantised to 1/16.4 deg/s, low-passed noise: near each peak the reading stays
  // on one step for tens of samples, but the motion either side peaks there too.
  std::mt19937 random(4);
  std::normal_distribution<double> noise(0.0, 0.0005);
  const double step = 3.14159265358979323846 / 180.0 / 16.4;
  Flight smooth, clipped;
  double filtered = 0.0;
  for (int k = 0; k < 8000; ++k) {
    const double t = k / 8000.0;
    filtered += 0.05 * (noise(random) - filtered);
    const double x = 10.0 * std::sin(2.0 * M_PI * 2.0 * t) + filtered;
    smooth.time_s.push_back(t);
    smooth.omega.push_back(
        Eigen::Vector3d(std::round(x / step) * step, 1.0 + noise(random), -2.0 + noise(random)));
    smooth.usable.push_back(1);
    clipped.time_s.push_back(t);
    clipped.omega.push_back(Eigen::Vector3d(std::round(std::clamp(x, -9.5, 9.5) / step) * step,
                                            1.0 + noise(random), -2.0 + noise(random)));
    clipped.usable.push_back(1);
  }
  CHECK(mark_saturated_samples(smooth).samples == 0);
  // The same motion clipped at 9.5 rad/s still has its flat tops found.
  std::size_t at_full_scale = 0;
  for (const Eigen::Vector3d& w : clipped.omega) at_full_scale += std::abs(w.x()) >= 9.5 - step;
  CHECK(mark_saturated_samples(clipped).samples >= at_full_scale * 9 / 10);
}
