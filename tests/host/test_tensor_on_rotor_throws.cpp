// The tensor estimate through the whole pipeline on generated throws of a body carrying a
// rotor whose speed the firmware logs as an ESC's telemetry gives it (generated_throws.hpp:
// 1-4 ms late, quantised, held between frames; the gyro behind a 2nd-order low-pass; a
// real IMU's bias, scale and axis errors): how close the absolute moments and the ratios
// come to the truth, and how often the 95 % intervals hold it. On the seeds the gyro's
// scale tolerance was measured on, a measurement (hidden); on fresh seeds, the held-back
// real throws' bars, asserted (docs/tensor-estimate.md, "Limits").
// NO_SENSOR_ERRORS: without the IMU's bias, scale and axis errors; ALOFT_ROTOR_TELEMETRY_EXACT
// (generated_throws.hpp): the speed read without the telemetry's delay and hold.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <catch2/catch.hpp>

#include "aloft/onboard/onboard_pipeline.hpp"
#include "pipeline_flights.hpp"

namespace {

using aloft_test::Recording;
using aloft_test::RecordingSpec;

struct Scores {
  int flights = 0, determined = 0, absolute = 0, moments_covered = 0, ratios_covered = 0;
  int spinning = 0, spinning_determined = 0;  // thrown with a spin of 3 rad/s or more
  int notes[5] = {};
  std::vector<double> moment_errors, ratio_errors;  // relative, |.|
};

std::vector<aloft::FlightResult<float>> replay(const Recording& rec) {
  aloft::OnboardPipelineSettings<float> settings;
  settings.check.sensor_to_body = rec.sensor_to_body.cast<float>();
  settings.imu_position_known = true;
  settings.imu_position_m = rec.imu_position_m.cast<float>();
  settings.rotor.axis = rec.rotor_axis.cast<float>();
  settings.rotor.inertia_kg_m2 = static_cast<float>(rec.rotor_inertia_kg_m2);
  // The gyro's 2nd-order Butterworth as the first-order filter of the same delay, √2/(2π fc).
  const double cutoff_hz = std::min(0.25 * rec.rate_hz, 500.0);
  settings.tensor.gyro_filter_us =
      static_cast<std::uint16_t>(std::lround(1e6 * std::sqrt(2.0) / (2 * M_PI * cutoff_hz)));
  aloft::InertiaTensor<float> inertia;
  REQUIRE(aloft::InertiaTensor<float>::make_from_tensor(rec.nominal_tensor.cast<float>(), inertia) ==
          aloft::Status::ok);
  aloft::OnboardPipeline<float, 8> pipeline(inertia, settings);
  return aloft_test::pipeline_flights(pipeline, rec);
}

// The spin the hand gave the flight the pipeline found (the true release nearest its own,
// within 50 ms; 0 if none).
double release_rate_rad_s(const Recording& rec, const aloft::FlightResult<float>& f) {
  const double release_s = static_cast<double>(f.release_us - rec.t0_us) * 1e-6;
  for (const aloft_test::TrueFlight& t : rec.flights)
    if (std::abs(t.release_s - release_s) < 0.05) return t.release_rate_rad_s;
  return 0.0;
}

void score(const Recording& rec, Scores& s) {
  Eigen::SelfAdjointEigenSolver<aloft::Mat3<double>> truth(rec.true_tensor);
  const aloft::Vec3<double> m = truth.eigenvalues();  // ascending
  for (const aloft::FlightResult<float>& f : replay(rec)) {
    ++s.flights;
    const aloft::TensorEstimate<float>& e = f.tensor;
    ++s.notes[static_cast<int>(e.note)];
    const bool spins = release_rate_rad_s(rec, f) >= 3.0;
    s.spinning += spins ? 1 : 0;
    s.spinning_determined += spins && e.determined ? 1 : 0;
    if (!e.determined) continue;
    ++s.determined;
    bool ratios_in = true;
    for (int i = 0; i < 2; ++i) {
      const double truth_ratio = m(i) / m(2), err = double(e.ratio(i)) - truth_ratio;
      s.ratio_errors.push_back(std::abs(err) / truth_ratio);
      ratios_in = ratios_in && std::abs(err) <= double(e.ratios_95[i]);
    }
    s.ratios_covered += ratios_in ? 1 : 0;
    if (!e.absolute) continue;
    ++s.absolute;
    bool moments_in = true;
    for (int i = 0; i < 3; ++i) {
      const double err = double(e.principal(i)) - m(i);
      s.moment_errors.push_back(std::abs(err) / m(i));
      moments_in = moments_in && std::abs(err) <= double(e.principal_95(i));
    }
    s.moments_covered += moments_in ? 1 : 0;
  }
}

double mean(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x;
  return v.empty() ? 0.0 : sum / static_cast<double>(v.size());
}

// Ten recordings at each of 1, 2 and 4 kHz, every third with the sensor turned in the body.
Scores score_recordings(std::uint32_t seed_base) {
  Scores s;
  for (double rate : {1000.0, 2000.0, 4000.0}) {
    for (int i = 0; i < 10; ++i) {
      RecordingSpec spec;
      spec.rate_hz = rate;
      spec.sensor_errors = std::getenv("NO_SENSOR_ERRORS") == nullptr;
      spec.rotor = true;
      spec.rotate_sensor = i % 3 == 1;
      spec.seed = seed_base + static_cast<std::uint32_t>(rate) * 100u + static_cast<std::uint32_t>(i);
      score(aloft_test::ThrowGenerator(spec).generate(), s);
    }
  }
  std::printf(
      "flights %d determined %d absolute %d; ratios mean |err| %.2f %% (covered %d); moments mean |err| %.2f "
      "%% (covered %d)\n",
      s.flights, s.determined, s.absolute, 100 * mean(s.ratio_errors), s.ratios_covered,
      100 * mean(s.moment_errors), s.moments_covered);
  std::printf("notes: determined %d too_short %d too_little_turning %d one_axis_spin %d not_a_tensor %d\n",
              s.notes[0], s.notes[1], s.notes[2], s.notes[3], s.notes[4]);
  std::printf("thrown with a spin of 3 rad/s or more: determined %d of %d\n", s.spinning_determined,
              s.spinning);
  return s;
}

}  // namespace

// The seeds the gyro's scale tolerance was measured on (docs/tensor-estimate.md, "Limits").
TEST_CASE("tensor estimate on generated rotor throws", "[.][tensor_rotor_throws]") {
  score_recordings(42000000u);
}

// Seeds used for nothing else: the held-back real throws' bars on errors (ratios 2 %,
// moments 3 %), coverage (80 %) of the moments and `determined` (40 of 45 throws: here of
// those thrown with a spin, 15 % of the generated throws leave the hand with none), and
// the ratios' intervals as honest.
TEST_CASE("tensor estimate on fresh rotor throws: within the bars, intervals that cover", "[tensor]") {
  const Scores s = score_recordings(43000000u);
  REQUIRE(s.absolute >= 60);
  CHECK(mean(s.ratio_errors) <= 0.02);
  CHECK(mean(s.moment_errors) <= 0.03);
  CHECK(s.moments_covered >= 0.8 * s.absolute);
  CHECK(s.ratios_covered >= 0.8 * s.determined);
  CHECK(s.spinning_determined * 45 >= s.spinning * 40);
}
