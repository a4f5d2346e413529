// The gyro filter's bend of the motion (2_model/gyro_filter_bend.hpp,
// LowPassShape::bend_s2): against the digital filters themselves and exact derivatives.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "diagnose/2_model/gyro_filter_bend.hpp"
#include "diagnose/4_judge/low_pass_shape.hpp"

using namespace aloft::host::diagnose;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The worst error, after the filter has settled, of a reading model of a slow sine passed
// through `stages` PT1s at `cutoff_hz`: the sine delayed by the stages' mean delay, plus
// `bend_s2` times its second derivative.
double worst_error(int stages, double cutoff_hz, double sample_hz, double sine_hz, double bend_s2) {
  const double dt = 1.0 / sample_hz, rc = 1.0 / (2.0 * kPi * cutoff_hz), k = dt / (rc + dt);
  const double w = 2.0 * kPi * sine_hz, delay = stages * rc;  // each stage's mean delay: (1 - k) / k dt = RC
  std::vector<double> y(static_cast<std::size_t>(stages), 0.0);
  double worst = 0.0;
  for (int n = 0; n < static_cast<int>(sample_hz); ++n) {  // 1 s
    double x = std::sin(w * n * dt);
    for (double& stage : y) x = stage += k * (x - stage);
    const double model = std::sin(w * (n * dt - delay)) - bend_s2 * w * w * std::sin(w * (n * dt - delay));
    if (n * dt > 0.5) worst = std::max(worst, std::abs(x - model));
  }
  return worst;
}

}  // namespace

TEST_CASE("a PT1's and a PT2's bend is half their impulse response's variance; a Butterworth's none",
          "[gyro_filter_bend]") {
  const double fs = 4000.0, fc = 50.0, dt = 1.0 / fs, rc = 1.0 / (2.0 * kPi * fc);
  const LowPassShape pt1(LowPassShape::Kind::first_order, fc, fs),
      pt2(LowPassShape::Kind::two_first_order, fc, fs);
  CHECK(pt1.bend_s2() == Approx(0.5 * rc * (rc + dt)).epsilon(1e-12));
  CHECK(pt2.bend_s2() == Approx(2.0 * pt1.bend_s2()).epsilon(1e-12));
  CHECK(LowPassShape(LowPassShape::Kind::butterworth, fc, fs).bend_s2() == 0.0);
  CHECK(LowPassShape(LowPassShape::Kind::first_order, 0.0, fs).bend_s2() == 0.0);
  // A 2 Hz sine through the filters themselves (w RC = 0.04): the delayed sine misses by the
  // bend, (w RC)^2 / 2 of it a stage; delayed and bent, by the third order's, (5/6) (w RC)^3
  // behind a PT1 and (8/3) (w RC)^3 behind two, at most 7 % and 11 % of the bend here (3 % measured).
  for (int stages : {1, 2}) {
    const double bend = stages == 1 ? pt1.bend_s2() : pt2.bend_s2();
    const double delayed = worst_error(stages, fc, fs, 2.0, 0.0),
                 bent = worst_error(stages, fc, fs, 2.0, bend);
    INFO(stages << " stages: delayed " << delayed << ", bent " << bent);
    CHECK(delayed > 7e-4 * stages);
    CHECK(bent < 0.1 * delayed);
  }
}

TEST_CASE("readings are bent by their second derivative, at uneven times and at the ends too",
          "[gyro_filter_bend]") {
  Flight flight;
  std::vector<Eigen::Vector3d> readings;
  double t = 0.0;
  for (int k = 0; k < 200; ++k) {
    flight.time_s.push_back(t);
    readings.push_back(Eigen::Vector3d(3.0 * t * t, -t * t + t, 1.0));  // second derivatives 6, -2, 0
    t += (k % 3 == 0) ? 0.0011 : 0.0007;
  }
  const std::vector<Eigen::Vector3d> before = readings;
  bend_by_gyro_filter(flight, readings);  // no bend: left alone
  CHECK(readings == before);
  flight.gyro_filter_bend_s2 = 1e-4;
  bend_by_gyro_filter(flight, readings);
  for (std::size_t k = 0; k < readings.size(); ++k) {
    const Eigen::Vector3d added = readings[k] - before[k];
    CHECK(added(0) == Approx(6e-4).epsilon(1e-9));
    CHECK(added(1) == Approx(-2e-4).epsilon(1e-9));
    CHECK(std::abs(added(2)) < 1e-15);
  }
  // Only the samples a fit reads are bent, each from its own run's readings: a fold of chunks
  // of 50 samples, the others' readings unread (here NaN) and left alone.
  std::vector<char> mask(readings.size()), usable(readings.size(), 1);
  readings = before;
  for (std::size_t k = 0; k < readings.size(); ++k) {
    mask[k] = (k / 50) % 2 == 0;
    if (!mask[k]) readings[k].setConstant(std::nan(""));
  }
  bend_by_gyro_filter(flight, readings, ReadSamples{mask.data(), usable.data()});
  for (std::size_t k = 0; k < readings.size(); ++k) {
    if (!mask[k]) {
      CHECK(std::isnan(readings[k](0)));
      continue;
    }
    CHECK(readings[k](0) - before[k](0) == Approx(6e-4).epsilon(1e-9));
    CHECK(readings[k](1) - before[k](1) == Approx(-2e-4).epsilon(1e-9));
  }
}
