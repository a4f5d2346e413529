// Release and landing of a spinning, off-centre IMU (aloft/onboard/onboard_pipeline.hpp) on a few
// hundred generated throws (generated_throws.hpp): the bars, the lever-arm
// estimate, drops, and no flight where there is none. Every case prints what it measured.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <vector>

#include "aloft/onboard/onboard_pipeline.hpp"
#include "pipeline_flights.hpp"

namespace {

using aloft_test::MotionKind;
using aloft_test::Recording;
using aloft_test::RecordingSpec;

struct Tally {
  int true_flights = 0;
  int found = 0;
  int release_within_5ms = 0;
  int release_within_10ms = 0;
  int landing_within_5ms = 0;
  int landing_within_10ms = 0;
  int early = 0;             // reported release before the true one
  int early_in_contact = 0;  // before the hand's force fell below 1 m/s² (generated_throws.hpp)
  int early_over_10ms = 0;   // more than 10 ms before the true release: the real throws' bar
  int before_retouch = 0;    // with a re-touch: dated before the finger touched again
  int within_judged = 0;     // from 10 ms early to 20 ms late: the held-back real throws' bar
  double worst_early_ms = 0;
  int false_flights = 0;  // reported where there was none
  int turned = 0;
  double worst_late_ms = 0;
  double worst_landing_ms = 0;
  int r_estimates = 0;      // recordings whose flights' r fits were trusted (the estimate's errors below)
  int r_not_estimated = 0;  // recordings where none was: each flight fitted its own r
  double worst_r_error_mm = 0;
  std::vector<double> r_errors_mm;

  void add(const Tally& o) {
    true_flights += o.true_flights;
    found += o.found;
    release_within_5ms += o.release_within_5ms;
    release_within_10ms += o.release_within_10ms;
    landing_within_5ms += o.landing_within_5ms;
    landing_within_10ms += o.landing_within_10ms;
    early += o.early;
    early_in_contact += o.early_in_contact;
    early_over_10ms += o.early_over_10ms;
    before_retouch += o.before_retouch;
    within_judged += o.within_judged;
    worst_early_ms = std::max(worst_early_ms, o.worst_early_ms);
    false_flights += o.false_flights;
    turned += o.turned;
    worst_late_ms = std::max(worst_late_ms, o.worst_late_ms);
    worst_landing_ms = std::max(worst_landing_ms, o.worst_landing_ms);
    r_estimates += o.r_estimates;
    r_not_estimated += o.r_not_estimated;
    worst_r_error_mm = std::max(worst_r_error_mm, o.worst_r_error_mm);
    r_errors_mm.insert(r_errors_mm.end(), o.r_errors_mm.begin(), o.r_errors_mm.end());
  }
  double percent(int n) const { return true_flights > 0 ? 100.0 * n / true_flights : 100.0; }
  void print(const char* name) const {
    std::printf(
        "%-34s flights %4d found %5.1f%% release<=5ms %5.1f%% <=10ms %5.1f%% (worst late %.2f ms) early %d "
        "(in contact %d, worst %.2f ms) -10..+20ms %5.1f%% landing<=5ms %5.1f%% <=10ms %5.1f%% (worst %.2f "
        "ms) "
        "false %d turned %d\n",
        name, true_flights, percent(found), percent(release_within_5ms), percent(release_within_10ms),
        worst_late_ms, early, early_in_contact, worst_early_ms, percent(within_judged),
        percent(landing_within_5ms), percent(landing_within_10ms), worst_landing_ms, false_flights, turned);
    if (early_over_10ms > 0 || before_retouch > 0) {
      std::printf("%-34s more than 10 ms early %d, dated before a re-touch %d\n", name, early_over_10ms,
                  before_retouch);
    }
    if (r_estimates > 0) {
      std::vector<double> e = r_errors_mm;
      std::sort(e.begin(), e.end());
      std::printf("%-34s r estimates %d (none in %d): median error %.2f mm, 90th %.2f mm, worst %.2f mm\n",
                  name, r_estimates, r_not_estimated, e[e.size() / 2], e[e.size() * 9 / 10], e.back());
    }
  }
};

aloft::InertiaTensor<float> nominal_tensor(const Recording& rec) {
  aloft::InertiaTensor<float> inertia;
  const aloft::Mat3<float> t = rec.nominal_tensor.cast<float>();
  REQUIRE(aloft::InertiaTensor<float>::make_from_tensor(t, inertia) == aloft::Status::ok);
  return inertia;
}

// Runs the float pipeline over a recording and collects its flights. r_error_m: the given
// r is off by this much (m), in one fixed direction. `estimate`: the recording's estimate of
// r after its flights, or null where no flight's fit was trusted.
std::vector<aloft::FlightResult<float>> replay(const Recording& rec, bool give_r,
                                               std::optional<aloft::Vec3<float>>* estimate,
                                               double r_error_m) {
  aloft::OnboardPipelineSettings<float> settings;
  settings.check.sensor_to_body = rec.sensor_to_body.cast<float>();
  settings.imu_position_known = give_r;
  // The window's settings from the environment, to repeat their choice on the tuned seeds
  // (docs/validation/release-detection.md, "Real hands"): ALOFT_WINDOW_FLOOR (m/s²), ALOFT_WINDOW_RELATIVE,
  // ALOFT_WINDOW_BLOCK_US.
  if (const char* v = std::getenv("ALOFT_WINDOW_FLOOR"))
    settings.release_window.block_limit_floor_m_s2 = std::strtof(v, nullptr);
  if (const char* v = std::getenv("ALOFT_WINDOW_RELATIVE"))
    settings.release_window.block_limit_relative = std::strtof(v, nullptr);
  if (const char* v = std::getenv("ALOFT_WINDOW_BLOCK_US"))
    settings.release_window.block_us = static_cast<std::uint32_t>(std::strtoul(v, nullptr, 10));
  const aloft_test::V3 off = aloft_test::V3(0.6, -0.48, 0.64) * r_error_m;
  settings.imu_position_m = (rec.imu_position_m + off).cast<float>();
  if (rec.rotor_inertia_kg_m2 > 0) {
    settings.rotor.axis = rec.rotor_axis.cast<float>();
    settings.rotor.inertia_kg_m2 = static_cast<float>(rec.rotor_inertia_kg_m2);
  }
  aloft::OnboardPipeline<float, 8> pipeline(nominal_tensor(rec), settings);
  std::vector<aloft::FlightResult<float>> flights = aloft_test::pipeline_flights(pipeline, rec);
  if (estimate != nullptr) {
    if (pipeline.has_imu_position_estimate()) *estimate = pipeline.imu_position_estimate();
  }
  return flights;
}

void score(const Recording& rec, bool give_r, Tally& t, double r_error_m) {
  std::optional<aloft::Vec3<float>> estimate;
  const auto flights = replay(rec, give_r, &estimate, r_error_m);
  std::vector<bool> used(flights.size(), false);
  for (const auto& truth : rec.flights) {
    ++t.true_flights;
    const double release_us = static_cast<double>(rec.t0_us) + truth.release_s * 1e6;
    const double landing_us = static_cast<double>(rec.t0_us) + truth.landing_s * 1e6;
    for (std::size_t i = 0; i < flights.size(); ++i) {
      const double r = static_cast<double>(flights[i].release_us);
      if (used[i] || r < release_us - 50e3 || r > landing_us) continue;
      used[i] = true;
      ++t.found;
      const double late_ms = (r - release_us) * 1e-3;
      const double land_ms = std::abs(static_cast<double>(flights[i].landing_us) - landing_us) * 1e-3;
      if (late_ms < 0) ++t.early;
      if (late_ms < -10) ++t.early_over_10ms;
      if (truth.retouch_start_s < truth.release_s &&
          r < static_cast<double>(rec.t0_us) + truth.retouch_start_s * 1e6)
        ++t.before_retouch;
      if (late_ms >= -10 && late_ms <= 20) ++t.within_judged;
      if (r < static_cast<double>(rec.t0_us) + truth.force_below_1_s * 1e6) ++t.early_in_contact;
      if (late_ms < 0) t.worst_early_ms = std::max(t.worst_early_ms, -late_ms);
      if (late_ms >= 0 && late_ms <= 5) ++t.release_within_5ms;
      if (late_ms >= 0 && late_ms <= 10) ++t.release_within_10ms;
      if (flights[i].landed && land_ms <= 5) ++t.landing_within_5ms;
      if (flights[i].landed && land_ms <= 10) ++t.landing_within_10ms;
      if (flights[i].turned) ++t.turned;
      t.worst_late_ms = std::max(t.worst_late_ms, late_ms);
      if (std::getenv("ALOFT_RELEASE_DEBUG") != nullptr && (late_ms < 0 || late_ms > 5 || land_ms > 5)) {
        std::printf(
            "  rate %g w %.1f late %.2f ms (contact ended %.2f ms before release) land %.2f ms landed %d\n",
            rec.rate_hz, truth.release_rate_rad_s, late_ms, (truth.release_s - truth.force_below_1_s) * 1e3,
            (static_cast<double>(flights[i].landing_us) - landing_us) * 1e-3, flights[i].landed);
      }
      t.worst_landing_ms = std::max(t.worst_landing_ms, land_ms);
      break;
    }
  }
  for (std::size_t i = 0; i < flights.size(); ++i) {
    if (used[i]) continue;
    ++t.false_flights;
    if (std::getenv("ALOFT_RELEASE_DEBUG") != nullptr) {
      std::printf("  rate %g: no true flight at %.4f to %.4f s\n", rec.rate_hz,
                  (static_cast<double>(flights[i].release_us) - static_cast<double>(rec.t0_us)) * 1e-6,
                  (static_cast<double>(flights[i].landing_us) - static_cast<double>(rec.t0_us)) * 1e-6);
    }
  }
  if (!give_r && rec.kind == MotionKind::spin_throw && !estimate) ++t.r_not_estimated;
  if (!give_r && rec.kind == MotionKind::spin_throw && estimate) {
    // The estimate after the whole recording against the truth (mm).
    const double error_mm = (estimate->cast<double>() - rec.imu_position_m).norm() * 1e3;
    ++t.r_estimates;
    t.r_errors_mm.push_back(error_mm);
    t.worst_r_error_mm = std::max(t.worst_r_error_mm, error_mm);
  }
}

// ALOFT_RELEASE_SEED_SHIFT=n draws a fresh set of recordings (default 0: the set the bars
// below were measured on), to see how the figures hold on throws nobody tuned against.
std::uint32_t seed_shift() {
  const char* shift = std::getenv("ALOFT_RELEASE_SEED_SHIFT");
  return shift != nullptr ? static_cast<std::uint32_t>(std::strtoul(shift, nullptr, 10)) * 100000u : 0u;
}

Tally run(MotionKind kind, const std::vector<double>& rates, int recordings, double tensor_error, bool give_r,
          std::uint32_t seed0, const char* name, double r_error_m = 0.0, bool sensor_errors = false,
          double interval_jitter = 0.0, bool real_hand = false, bool retouch = false, bool rotor = false) {
  Tally t;
  for (double rate : rates) {
    Tally per_rate;
    for (int i = 0; i < recordings; ++i) {
      RecordingSpec spec;
      spec.kind = kind;
      spec.rate_hz = rate;
      spec.tensor_error = tensor_error;
      spec.rotate_sensor = i % 3 == 1;
      spec.sensor_errors = sensor_errors;
      spec.interval_jitter = interval_jitter;
      spec.real_hand = real_hand;
      spec.retouch = retouch;
      spec.rotor = rotor;
      spec.seed =
          seed0 + static_cast<std::uint32_t>(i) + static_cast<std::uint32_t>(rate) * 1000u + seed_shift();
      const Recording rec = aloft_test::ThrowGenerator(spec).generate();
      score(rec, give_r, per_rate, r_error_m);
    }
    t.add(per_rate);
    char label[64];
    std::snprintf(label, sizeof label, "%s @ %g Hz", name, rate);
    per_rate.print(label);
  }
  t.print(name);
  return t;
}

}  // namespace

// Measured (printed below, gcc Release): r given 100 % within 5 ms, none early; r fitted
// with I 15 % off 100 % within 10 ms (98.1 % before the lever-arm estimator trusted a
// flight's r only within its worst error, lever_arm_estimator.hpp), none early; r given 3 mm off 97.8 %
// within 10 ms (the detector fits an r near the given one, release_detector.hpp), none early: one flight
// broken in two, whose first 59 ms are now dropped as too short (min_flight_us).
TEST_CASE("release and landing with r given and the right tensor at 1 to 4 kHz", "[release]") {
  const Tally t = run(MotionKind::spin_throw, {1000, 2000, 4000}, 30, 0.0, true, 100, "spin, r given");
  CHECK(t.early == 0);
  CHECK(t.false_flights == 0);
  CHECK(t.percent(t.release_within_5ms) >= 98.0);
  CHECK(t.percent(t.landing_within_5ms) >= 98.0);
}

TEST_CASE("release with a given r that is 3 mm off and the tensor 15 % wrong", "[release]") {
  const Tally t =
      run(MotionKind::spin_throw, {1000, 4000}, 15, 0.15, true, 800, "spin, r 3 mm off, I 15% off", 0.003);
  CHECK(t.early == 0);
  CHECK(t.percent(t.false_flights) <= 2.0);
  CHECK(t.percent(t.release_within_10ms) >= 95.0);
  CHECK(t.percent(t.landing_within_10ms) >= 95.0);
}

TEST_CASE("release and landing without r and with the tensor 15 % wrong at 1 to 4 kHz", "[release]") {
  const Tally t =
      run(MotionKind::spin_throw, {1000, 2000, 4000}, 30, 0.15, false, 200, "spin, r fitted, I 15% off");
  CHECK(t.early == 0);
  CHECK(t.percent(t.false_flights) <= 1.0);
  CHECK(t.percent(t.release_within_10ms) >= 95.0);
  CHECK(t.percent(t.landing_within_10ms) >= 95.0);
  // The recording's estimate of r after its flights (each recording: one body, one r).
  std::vector<double> e = t.r_errors_mm;
  std::sort(e.begin(), e.end());
  // Measured: 88 of 90 recordings keep an estimate, median 0.13 mm, 90th 0.43 mm, worst
  // 1.35 mm (on seed shifts 1-3: 81-86 of 90, worst 1.61 mm; up to 35 mm before the
  // lever-arm estimator trusted a flight's r only within its worst error).
  REQUIRE(e.size() >= 80u);
  CHECK(e[e.size() / 2] < 0.5);
  CHECK(e[e.size() * 9 / 10] < 2.0);
  CHECK(e.back() < 5.0);
}

// A real IMU is not only noisy: biases, scale errors and the accelerometer's axes a little
// off the gyro's (generated_throws.hpp, pick_sensor_errors). Measured (gcc Release): r
// given 100 % within 5 ms; r fitted with I 15 % off 99.2 % within 10 ms; drops 100 %; no
// false flight, none early.
TEST_CASE("release and landing with a real IMU's bias, scale and axis errors", "[release]") {
  constexpr double no_r_error = 0.0;
  constexpr bool with_sensor_errors = true;
  const Tally given = run(MotionKind::spin_throw, {1000, 4000}, 20, 0.0, true, 900, "errors, r given",
                          no_r_error, with_sensor_errors);
  const Tally fitted = run(MotionKind::spin_throw, {1000, 4000}, 20, 0.15, false, 1000,
                           "errors, r fitted, I 15% off", no_r_error, with_sensor_errors);
  const Tally drops = run(MotionKind::drop, {100, 1000}, 8, 0.15, false, 1100, "errors, drop", no_r_error,
                          with_sensor_errors);
  const Tally waving = run(MotionKind::waving, {100, 1000}, 8, 0.15, false, 1200, "errors, waving",
                           no_r_error, with_sensor_errors);
  for (const Tally* t : {&given, &fitted, &drops}) {
    CHECK(t->early == 0);
    CHECK(t->false_flights == 0);
    CHECK(t->percent(t->release_within_10ms) >= 95.0);
    CHECK(t->percent(t->landing_within_10ms) >= 95.0);
  }
  CHECK(waving.false_flights == 0);
}

TEST_CASE("release and landing at 100 and 250 Hz: found, never early", "[release]") {
  const Tally given = run(MotionKind::spin_throw, {100, 250}, 15, 0.0, true, 300, "spin, r given");
  const Tally fitted =
      run(MotionKind::spin_throw, {100, 250}, 15, 0.15, false, 400, "spin, r fitted, I 15% off");
  for (const Tally* t : {&given, &fitted}) {
    CHECK(t->early == 0);
    CHECK(t->false_flights == 0);
    CHECK(t->percent(t->found) >= 95.0);
  }
  // Measured (gcc Release): release r given 100 % within 10 ms (worst 8.95 ms late), r
  // fitted 100 % (worst 9.08 ms); landing 98.9 % and 98.9 % within 10 ms.
  CHECK(given.percent(given.release_within_10ms) >= 98.0);
  CHECK(fitted.percent(fitted.release_within_10ms) >= 90.0);
  CHECK(given.percent(given.landing_within_10ms) >= 95.0);
  CHECK(fitted.percent(fitted.landing_within_10ms) >= 90.0);
}

// Another device, other rates: a logger without a hardware clock at 200 to 700 Hz, each
// sampling interval 3 % either way, with a real IMU's errors. Measured (gcc Release):
// drops 100 % within 10 ms (worst 8.4 ms late), landing 100 %; r fitted with I 15 % off
// 99.3 % within 10 ms, landing 99.3 %; none early, no false flight, waving included.
// Before releases were dated from the steepest fall (release_detector.hpp,
// after_fade_out), spinning throws at 400 Hz came 63 % within 10 ms.
TEST_CASE("drops and throws logged with irregular intervals at 200 and 400 Hz", "[release]") {
  constexpr double no_r_error = 0.0;
  constexpr bool with_sensor_errors = true;
  constexpr double jitter = 0.03;
  const Tally drops = run(MotionKind::drop, {200, 300, 400, 500, 700}, 8, 0.15, false, 1300, "jitter, drop",
                          no_r_error, with_sensor_errors, jitter);
  const Tally fitted = run(MotionKind::spin_throw, {200, 300, 400, 500, 700}, 10, 0.15, false, 1400,
                           "jitter, r fitted, I 15% off", no_r_error, with_sensor_errors, jitter);
  const Tally waving = run(MotionKind::waving, {200, 300, 400, 500, 700}, 6, 0.15, false, 1500,
                           "jitter, waving", no_r_error, with_sensor_errors, jitter);
  for (const Tally* t : {&drops, &fitted}) {
    CHECK(t->early == 0);
    CHECK(t->false_flights == 0);
    CHECK(t->percent(t->release_within_10ms) >= 95.0);
    CHECK(t->percent(t->landing_within_10ms) >= 95.0);
  }
  CHECK(drops.turned == 0);
  CHECK(waving.false_flights == 0);
}

TEST_CASE("drops from rest are found and do not count as turned", "[release]") {
  const Tally t = run(MotionKind::drop, {100, 250, 1000, 4000}, 8, 0.15, false, 500, "drop, r fitted");
  CHECK(t.early == 0);
  CHECK(t.false_flights == 0);
  CHECK(t.percent(t.found) >= 98.0);
  CHECK(t.turned == 0);
  // Measured: release and landing 100 % within 10 ms at every rate (worst 8.9 ms late
  // release and 7.9 ms landing, at 100 Hz).
  CHECK(t.percent(t.release_within_10ms) >= 98.0);
  CHECK(t.percent(t.landing_within_10ms) >= 98.0);
}

TEST_CASE("no flight in a recording without one", "[release]") {
  for (const bool give_r : {true, false}) {
    const Tally still = run(MotionKind::still, {100, 1000, 4000}, 4, 0.0, give_r, 600, "still");
    const Tally waving =
        run(MotionKind::waving, {100, 1000, 4000}, 8, 0.15, give_r, 700, "waving, no release");
    CHECK(still.false_flights == 0);
    CHECK(waving.false_flights == 0);
  }
}

// Real hands (generated_throws.hpp, real_hand): a let-go over 2-30 ms with a slow tail, the
// hand's torque to the end, a body that rings after release and after a catch, at 1-4 kHz
// (the held-back real throws: 4 kHz; real drops: 2-3 kHz). The window's settings
// (aloft/onboard/release_window.hpp) were chosen on the first seed set ("tuned on") and are
// reported on the second, drawn from seeds nobody looked at while choosing them ("held
// out"); both must meet the held-back real throws' bar: within 10 ms early to 20 ms late,
// never more than 10 ms early. Measured (gcc Release), docs/validation/release-detection.md, "Real hands".
namespace {
// Three sets at 1, 2 and 4 kHz with a real IMU's errors, named "LABEL, r given", ...: 15
// spinning throws a rate with r given (seeds from seed0), 15 with r fitted and the tensor
// 15 % off (seed0 + 100), 6 drops (seed0 + 200).
struct HandSets {
  Tally given, fitted, drops;
};
HandSets run_hand_sets(std::uint32_t seed0, const char* label, bool real_hand, bool retouch) {
  constexpr double no_r_error = 0.0;
  constexpr bool with_sensor_errors = true;
  constexpr double no_jitter = 0.0;
  char name[3][64];
  std::snprintf(name[0], sizeof name[0], "%s, r given", label);
  std::snprintf(name[1], sizeof name[1], "%s, r fitted, I 15%% off", label);
  std::snprintf(name[2], sizeof name[2], "%s, drop", label);
  HandSets s;
  s.given = run(MotionKind::spin_throw, {1000, 2000, 4000}, 15, 0.0, true, seed0, name[0], no_r_error,
                with_sensor_errors, no_jitter, real_hand, retouch);
  s.fitted = run(MotionKind::spin_throw, {1000, 2000, 4000}, 15, 0.15, false, seed0 + 100, name[1],
                 no_r_error, with_sensor_errors, no_jitter, real_hand, retouch);
  s.drops = run(MotionKind::drop, {1000, 2000, 4000}, 6, 0.15, false, seed0 + 200, name[2], no_r_error,
                with_sensor_errors, no_jitter, real_hand, retouch);
  return s;
}
constexpr bool kRealHand = true;
constexpr bool kRetouch = true;
}  // namespace

TEST_CASE("release on real hands: slow let-go, hand torque, ringing body", "[release][real_hand]") {
  const HandSets tuned = run_hand_sets(1600, "real hand tuned on", kRealHand, !kRetouch);
  const HandSets held_out = run_hand_sets(2600, "real hand held out", kRealHand, !kRetouch);
  for (const HandSets* s : {&tuned, &held_out}) {
    for (const Tally* t : {&s->given, &s->fitted, &s->drops}) {
      CHECK(t->worst_early_ms <= 10.0);
      CHECK(t->false_flights == 0);
      CHECK(t->percent(t->found) >= 97.0);
    }
  }
}

// A finger that touches again as the body leaves (generated_throws.hpp, retouch): the
// hand's force falls away, is gone for 2-4 ms, a finger pushes for 5-15 ms at 3-4 m/s²
// with a torque, then the hand is gone; the true release is after the finger. The one
// held-back real throw released early (14.9 ms) was this. Seeds 4600- (fast hand) and
// 5600- (real hand) were drawn for this case; the rules that date a finger's release were
// chosen on them and are reported on ALOFT_RELEASE_SEED_SHIFT 1 and 2. The bars are
// the project's: a fast hand never early, as every fast-hand case; a real hand (slow
// let-go, hand torque, ringing) never more than 10 ms early, as "release on real hands".
// The real hand's case meets its bar since the release window tests each block's torque
// too (docs/validation/release-detection.md, "A finger's re-touch": worst 7.65 ms early).
// The fast hand's met it once a finger's end was taken as quadratic (it lifts off at zero
// slope) in the detector's fine dating and the window's tail, and a later look dated anew a
// release the first look had moved: before, 5 of 324 early, each in the finger's last fall
// after its force fell under 1 m/s² (worst 0.35 ms). Both run in the suite.
TEST_CASE("release after a finger's re-touch, fast hand: never early", "[release][retouch]") {
  const HandSets s = run_hand_sets(4600, "re-touch fast hand", !kRealHand, kRetouch);
  for (const Tally* t : {&s.given, &s.fitted, &s.drops}) {
    CHECK(t->early == 0);
    CHECK(t->false_flights == 0);
    CHECK(t->percent(t->found) >= 97.0);
  }
}

TEST_CASE("release after a finger's re-touch, real hand: never more than 10 ms early",
          "[release][retouch][real_hand]") {
  const HandSets s = run_hand_sets(5600, "re-touch real hand", kRealHand, kRetouch);
  for (const Tally* t : {&s.given, &s.fitted, &s.drops}) {
    CHECK(t->worst_early_ms <= 10.0);
    CHECK(t->false_flights == 0);
    CHECK(t->percent(t->found) >= 97.0);
  }
}

// The generator's rotor (generated_throws.hpp, rotor): in flight the body is the
// gyrostat, so its total angular momentum R(q) (I ω + h) in world axes is the same at the
// landing as at the release, and the rotor turned in flight.
TEST_CASE("generated rotor throws conserve the world angular momentum in flight", "[release][rotor]") {
  int flights = 0;
  for (std::uint32_t seed = 7600; seed < 7610; ++seed) {
    RecordingSpec spec;
    spec.rotor = true;
    spec.seed = seed;
    const Recording rec = aloft_test::ThrowGenerator(spec).generate();
    double peak = 0.0;
    for (const auto& sample : rec.samples) {
      REQUIRE(sample.has_rotor_speed());
      peak = std::max(peak, std::abs(sample.rotor_rad_s));
    }
    CHECK(peak >= 300.0);
    for (const aloft_test::TrueFlight& f : rec.flights) {
      if (f.rotor_profile.full_rad_s == 0.0) continue;  // a throw without a turn: no rotor run
      ++flights;
      // A throw released without a turn has L = 0: the rotor's full momentum is the scale.
      const double l = f.momentum_world_release.norm();
      const double h = rec.rotor_inertia_kg_m2 * std::abs(f.rotor_profile.full_rad_s);
      INFO("seed " << seed << " release " << f.release_s << " s: |L| " << l << ", |h| at full speed " << h);
      CHECK((f.momentum_world_landing - f.momentum_world_release).norm() <= 1e-9 * (l + h));
      // The rotor ran in flight, and its share of |L| is not small.
      CHECK(f.rotor_profile.start_s < f.landing_s);
      CHECK(h > 0.01 * l);
    }
  }
  CHECK(flights >= 20);
}

// Throws of a body with a rotor whose speed is logged (generated_throws.hpp, rotor): the
// wheel spins up from rest after the release, holds full speed and brakes, mostly in
// flight; its torque is known from the logged speed, so it is never a landing
// (aloft/onboard/torque_test.hpp). Seeds 8600- (fast hand) and 9600- (real hand), on which
// nothing was chosen (the torque test's design was chosen on shifts 1 and 2 of
// ALOFT_RELEASE_SEED_SHIFT), 1, 2 and 4 kHz with a real IMU's errors, held to the bars of
// the cases without a rotor: release never early (real hand: never more than 10 ms early),
// no false flight, landings within 10 ms. Measured (gcc Release,
// docs/validation/release-detection.md, "A body with a rotor"): fast hand none early, no
// false flight, landings 98.5-100 % within 10 ms; real hand worst 7.0 ms early (10.1 ms
// before the release window tested each block's torque where the rotor had not yet turned).
namespace {
struct RotorSets {
  Tally given, fitted;
};
RotorSets run_rotor(std::uint32_t seed0, bool real_hand, const char* set) {
  constexpr double no_r_error = 0.0;
  constexpr bool with_sensor_errors = true;
  constexpr double no_jitter = 0.0;
  constexpr bool no_retouch = false;
  // ALOFT_RELEASE_NO_ROTOR: the same throws without their rotor, to compare.
  const bool rotor = std::getenv("ALOFT_RELEASE_NO_ROTOR") == nullptr;
  char name[2][64];
  std::snprintf(name[0], sizeof name[0], "rotor %s, r given", set);
  std::snprintf(name[1], sizeof name[1], "rotor %s, r fitted, I 15%% off", set);
  RotorSets s;
  s.given = run(MotionKind::spin_throw, {1000, 2000, 4000}, 15, 0.0, true, seed0, name[0], no_r_error,
                with_sensor_errors, no_jitter, real_hand, no_retouch, rotor);
  s.fitted = run(MotionKind::spin_throw, {1000, 2000, 4000}, 15, 0.15, false, seed0 + 100, name[1],
                 no_r_error, with_sensor_errors, no_jitter, real_hand, no_retouch, rotor);
  return s;
}
}  // namespace

TEST_CASE("release and landing of a body with a logged rotor, fast hand", "[release][rotor_throws]") {
  const RotorSets s = run_rotor(8600, false, "fast hand");
  for (const Tally* t : {&s.given, &s.fitted}) {
    CHECK(t->early == 0);
    CHECK(t->false_flights == 0);
    CHECK(t->percent(t->found) >= 97.0);
    CHECK(t->percent(t->landing_within_10ms) >= 95.0);
  }
}

TEST_CASE("release and landing of a body with a logged rotor, real hand",
          "[release][rotor_throws][real_hand]") {
  const RotorSets s = run_rotor(9600, true, "real hand");
  for (const Tally* t : {&s.given, &s.fitted}) {
    CHECK(t->worst_early_ms <= 10.0);
    CHECK(t->false_flights == 0);
    CHECK(t->percent(t->found) >= 97.0);
    CHECK(t->percent(t->landing_within_10ms) >= 95.0);
  }
}
