// The onboard pipeline on an exactly known sequence: held still, a torque-free spin about
// a principal axis with the IMU 30 mm off the axis (it reads w x (w x r), 12 m/s²),
// an impact, held again. Release and landing, the fitted r, gaps and clipped samples.
#include "aloft/onboard/onboard_pipeline.hpp"
#include "test_api.hpp"

#include <cmath>
#include <limits>

namespace {

using aloft::Status;
using aloft::Vec3;

// Samples every 1 ms from t = 1 s; flight over samples [500, 1200); a gap of `gap_us`
// before sample 1500 (flagged), sample 900's gyro clipped.
template <typename S>
aloft::ImuSample<S> sample_at(int k, std::uint64_t gap_us, bool flag_gap) {
  aloft::ImuSample<S> s;
  s.t_us = 1000000u + static_cast<std::uint64_t>(k) * 1000u + (k >= 1500 ? gap_us : 0u);
  const bool flying = k >= 500 && k < 1200;
  const Vec3<S> spin(S(0), S(0), S(20));
  const Vec3<S> r(S(0.03), S(0), S(0));
  s.gyro_rad_s = flying ? spin : Vec3<S>::Zero();
  s.accel_m_s2 =
      flying ? Vec3<S>(spin.cross(spin.cross(r))) : Vec3<S>(S(0), S(0), k == 1200 ? S(300) : S(9.81));
  if (k == 1500 && flag_gap) s.flags = aloft::imu_gap_before;
  if (k == 900) s.flags = aloft::imu_gyro_clipped;
  return s;
}

template <typename S>
aloft::InertiaTensor<S> box() {
  aloft::InertiaTensor<S> inertia;
  ALOFT_REQUIRE(aloft::InertiaTensor<S>::make_box(S(0.5), S(0.05), S(0.08), S(0.12), inertia) == Status::ok);
  return inertia;
}

template <typename S>
void one_spinning_flight(bool r_known) {
  aloft::OnboardPipelineSettings<S> settings;
  settings.imu_position_known = r_known;
  settings.imu_position_m = Vec3<S>(S(0.03), S(0), S(0));
  aloft::OnboardPipeline<S, 8> pipeline(box<S>(), settings);
  aloft::FlightResult<S> flight;
  int flights = 0;
  for (int k = 0; k < 2000; ++k) {
    ALOFT_REQUIRE(pipeline.push(sample_at<S>(k, 5000, true)) == Status::ok);
    while (pipeline.take_finished_flight(flight)) ++flights;
  }
  pipeline.finish();
  ALOFT_CHECK(!pipeline.take_finished_flight(flight));
  ALOFT_REQUIRE(flights == 1);
  // Release at sample 500 (t = 1.5 s), never before it, at most 5 ms after.
  ALOFT_CHECK(flight.release_us >= 1500000u);
  ALOFT_CHECK(flight.release_us <= 1505000u);
  ALOFT_CHECK(flight.landed);
  ALOFT_CHECK(flight.landing_us >= 2195000u);
  ALOFT_CHECK(flight.landing_us <= 2205000u);
  ALOFT_CHECK(flight.turned);
  ALOFT_CHECK(flight.clipped_samples == 1u);  // sample 900: not compared
  ALOFT_CHECK(flight.samples >= 680u);
  ALOFT_CHECK(flight.samples <= 699u);
  ALOFT_CHECK(flight.overall.rms_da() < S(1e-3));  // the right tensor: the check agrees
  ALOFT_CHECK(flight.imu_position_estimated == !r_known);
  ALOFT_CHECK((flight.imu_position_m - settings.imu_position_m).norm() < S(1e-3));
  ALOFT_CHECK(pipeline.stream().samples == 2000u);
  ALOFT_CHECK(pipeline.stream().gaps == 1u);
  ALOFT_CHECK(pipeline.stream().lost_us == 6000u);
  ALOFT_CHECK(pipeline.stream().clipped_samples == 1u);
}

// A stamp jump far beyond the sample interval counts as a gap even without the flag;
// one longer than end_flight_after_gap_us while airborne ends the flight unlanded.
template <typename S>
void gap_ends_flight() {
  aloft::OnboardPipelineSettings<S> settings;
  settings.imu_position_known = true;
  settings.imu_position_m = Vec3<S>(S(0.03), S(0), S(0));
  aloft::OnboardPipeline<S, 8> pipeline(box<S>(), settings);
  aloft::FlightResult<S> flight;
  int flights = 0, ended_by_gap = 0;
  for (int k = 0; k < 2000; ++k) {
    aloft::ImuSample<S> s = sample_at<S>(k < 1000 ? k : k - 1000 + 600, 0, false);
    s.t_us = 1000000u + static_cast<std::uint64_t>(k) * 1000u + (k >= 1000 ? 300000u : 0u);
    s.flags = 0;
    ALOFT_REQUIRE(pipeline.push(s) == Status::ok);
    while (pipeline.take_finished_flight(flight)) {
      ++flights;
      if (k != 1000) continue;
      // The flight the gap ended: unlanded, ending at the last sample before the gap.
      ++ended_by_gap;
      ALOFT_CHECK(!flight.landed);
      ALOFT_CHECK(flight.landing_us == 1000000u + 999u * 1000u);
    }
    if (k == 999) ALOFT_CHECK(pipeline.airborne());
    if (k == 1000) ALOFT_CHECK(!pipeline.airborne());
  }
  ALOFT_CHECK(ended_by_gap == 1);
  ALOFT_CHECK(flights >= 1);
  ALOFT_CHECK(pipeline.stream().gaps == 1u);
  ALOFT_CHECK(pipeline.stream().lost_us == 301000u);
}

// A slow spin whose IMU sits 30 mm further out than the given r: a flight that hardly turns
// fixes r poorly (docs/onboard-pipeline.md, "The lever arm r"). The flight's own fit,
// which takes over for the landing, is kept on the surface of the ball of
// given_r_tolerance_m about the given r; with no r given it is the fit itself, farther out.
template <typename S>
void flight_r_kept_near_given(bool r_known) {
  const Vec3<S> given(S(0.03), S(0), S(0));
  const Vec3<S> truth(S(0.06), S(0), S(0));
  const Vec3<S> spin(S(0), S(0), S(5));
  aloft::OnboardPipelineSettings<S> settings;
  settings.imu_position_known = r_known;
  settings.imu_position_m = given;
  aloft::OnboardPipeline<S, 8> pipeline(box<S>(), settings);
  aloft::ImuSample<S> s;
  for (int k = 0; k < 900; ++k) {
    const bool flying = k >= 500;
    s.t_us = 1000000u + static_cast<std::uint64_t>(k) * 1000u;
    s.gyro_rad_s = flying ? spin : Vec3<S>::Zero();
    s.accel_m_s2 = flying ? Vec3<S>(spin.cross(spin.cross(truth))) : Vec3<S>(S(0), S(0), S(9.81));
    ALOFT_REQUIRE(pipeline.push(s) == Status::ok);
  }
  ALOFT_REQUIRE(pipeline.airborne());
  const S off_m = (pipeline.flight_lever_arm() - given).norm();
  const S within = settings.release.given_r_tolerance_m;
  if (r_known) {
    ALOFT_CHECK(std::abs(off_m - within) < S(1e-4));
    ALOFT_CHECK(pipeline.flight_lever_arm().x() > given.x());  // towards the flight's fit
  } else {
    ALOFT_CHECK(off_m > S(1.5) * within);
  }
}

}  // namespace

ALOFT_TEST_CASE("pipeline: a flight's own r is kept within given_r_tolerance_m of a given r", "[pipeline]") {
  flight_r_kept_near_given<double>(true);
  flight_r_kept_near_given<double>(false);
  flight_r_kept_near_given<float>(true);
  flight_r_kept_near_given<float>(false);
}

ALOFT_TEST_CASE("pipeline: release and landing of a spinning off-centre IMU, r known or fitted",
                "[pipeline]") {
  one_spinning_flight<double>(true);
  one_spinning_flight<double>(false);
  one_spinning_flight<float>(true);
  one_spinning_flight<float>(false);
}

ALOFT_TEST_CASE("pipeline: a long gap while airborne ends the flight unlanded", "[pipeline]") {
  gap_ends_flight<double>();
  gap_ends_flight<float>();
}

ALOFT_TEST_CASE("pipeline: bad samples are refused and change nothing", "[pipeline][bad-input]") {
  aloft::OnboardPipeline<float, 8> pipeline(box<float>(), aloft::OnboardPipelineSettings<float>());
  ALOFT_CHECK(pipeline.push(sample_at<float>(0, 0, false)) == Status::ok);
  aloft::ImuSample<float> same = sample_at<float>(1, 0, false);
  same.t_us = sample_at<float>(0, 0, false).t_us;
  ALOFT_CHECK(pipeline.push(same) == Status::time_not_increasing);
  aloft::ImuSample<float> nan = sample_at<float>(1, 0, false);
  nan.accel_m_s2.x() = std::numeric_limits<float>::quiet_NaN();
  ALOFT_CHECK(pipeline.push(nan) == Status::non_finite_input);
  ALOFT_CHECK(pipeline.stream().samples == 1u);
}
