// The onboard pipeline: IMU samples in (aloft/sensor/imu_sample.hpp), one result per flight out.
// It is what a firmware runs behind its sensor driver and what `aloft replay` runs on a
// recording, the same code in `float`:
//   samples -> the stream clock (aloft/sensor/stream_clock.hpp: dt from time stamps, gaps,
//              clipping), sensor -> body axes
//           -> the last 32 samples (aloft/onboard/sample_history.hpp)
//           -> release and landing of a spinning, off-centre IMU (aloft/onboard/release_detector.hpp),
//              the release dated anew over a window (aloft/onboard/release_window.hpp)
//           -> the onboard check (aloft/onboard/onboard_check.hpp) over the airborne samples, fed
//              from the history from the (dated back) release on, never past the landing,
//              and the tensor estimate (aloft/onboard/tensor_estimator.hpp) over the same samples,
//              with the rotor's speed where there is one
//           -> FlightResult, taken by the caller once the flight has ended (the tensor estimate
//              is solved then, outside push: finished_flight()).
// This file is the flight's state machine: on the ground (find_release), on probation
// (the release window), airborne (find_landing), and the feeding of the check. A gap
// longer than `bridge_gap_up_to_us` ends the live simulations (they are seeded anew after
// it); while airborne, a gap longer than `end_flight_after_gap_us` ends the flight
// unlanded. A clipped gyro sample is not a measurement: it is neither compared nor used
// for detection. The accelerometer's position r: from the settings
// (`imu_position_known`), else estimated flight by flight (aloft/onboard/lever_arm_estimator.hpp).
#pragma once

#include <cstdint>
#include <new>
#include <optional>
#include <type_traits>

#include "aloft/cold_path.hpp"
#include "aloft/dynamics/rotor.hpp"
#include "aloft/sensor/imu_sample.hpp"
#include "aloft/onboard/lever_arm_estimator.hpp"
#include "aloft/onboard/onboard_check.hpp"
#include "aloft/onboard/release_detector.hpp"
#include "aloft/onboard/release_window.hpp"
#include "aloft/onboard/tensor_estimator.hpp"
#include "aloft/settings.hpp"
#include "aloft/sensor/stream_clock.hpp"
#include "aloft/sensor/whole_microseconds.hpp"

namespace aloft {

template <typename Scalar>
struct OnboardPipelineSettings {
  OnboardCheckSettings<Scalar> check = {};
  bool imu_position_known = false;
  Vec3<Scalar> imu_position_m = Vec3<Scalar>::Zero();
  Rotor<Scalar> rotor = {};  // none by default (aloft/dynamics/rotor.hpp)
  std::uint32_t bridge_gap_up_to_us = 20000;
  std::uint32_t end_flight_after_gap_us = 200000;
  StreamClockSettings<Scalar> clock = {};
  ReleaseDetectorSettings<Scalar> release = {};
  ReleaseWindowSettings<Scalar> release_window = {};
  LeverArmEstimatorSettings<Scalar> lever_arm = {};
  TensorEstimatorSettings<Scalar> tensor = {};
  std::uint32_t min_flight_us = 100000;
  std::uint32_t rearm_after_landing_us = 300000;
  Scalar turned_at_least_rad = Scalar(0.5);
  std::uint16_t feed_lag_samples = 8;

  // The one list of the pipeline's settings, its parts' included (aloft/settings.hpp).
  template <typename Self, typename Visitor>
  static void visit(Self& s, Visitor&& v) {
    visit_settings(s.check, v);
    visit_own(s, v);
    visit_settings(s.rotor, v);
    visit_settings(s.clock, v);
    visit_settings(s.release, v);
    visit_settings(s.release_window, v);
    visit_settings(s.lever_arm, v);
    visit_settings(s.tensor, v);
  }

 private:
  template <typename Self, typename Visitor>
  static void visit_own(Self& s, Visitor& v) {
    v(s.imu_position_known, [] {
      return SettingInfo{"imu_position_known", "",
                         "the body file gives imu.position: r is taken from imu_position_m, else it is "
                         "estimated from the data. A property of the body"};
    });
    v(s.imu_position_m, [] {
      return SettingInfo{"imu_position_m", "m",
                         "the accelerometer's position from the centre of mass, body axes: measured on "
                         "the body, not tuned"};
    });
    v(s.bridge_gap_up_to_us, [] {
      return SettingInfo{"bridge_gap_up_to_us", "µs",
                         "a longer gap ends the live simulations; they are seeded anew after it. Not swept: "
                         "20 samples at 1 kHz"};
    });
    v(s.end_flight_after_gap_us, [] {
      return SettingInfo{"end_flight_after_gap_us", "µs",
                         "a longer gap while airborne ends the flight unlanded. Not swept"};
    });
    v(s.min_flight_us, [] {
      return SettingInfo{"min_flight_us", "µs",
                         "shorter flights are dropped: a 5 cm drop; with r fitted, a lever arm fitted to "
                         "a waving hand explained its force for up to 80 ms in generated recordings"};
    });
    v(s.rearm_after_landing_us, [] {
      return SettingInfo{"rearm_after_landing_us", "µs",
                         "no release this soon after a landing (bounces). Not swept"};
    });
    v(s.turned_at_least_rad, [] {
      return SettingInfo{"turned_at_least_rad", "rad",
                         "FlightResult::turned: a flight that turned less (the integral of |w|) is a drop "
                         "and gets no DA. Not swept"};
    });
    v(s.feed_lag_samples, [] {
      return SettingInfo{"feed_lag_samples", "samples",
                         "the check is fed this far behind the newest sample, so a landing (3 samples of "
                         "evidence, dated back a few more) can still be dated back over them. Derived"};
    });
  }
};

// The samples the pipeline holds back (OnboardPipeline::history_samples).
constexpr int onboard_history_samples = 32;

// What a firmware fixes when it is compiled; the records' settings hash takes these too.
struct OnboardBuildConstants {
  std::uint16_t live_simulations = 0;
  std::uint16_t history_samples = 0;
  std::uint16_t release_window_blocks = 0;

  // The one list of them (aloft/settings.hpp).
  template <typename Self, typename Visitor>
  static void visit(Self& s, Visitor&& v) {
    v(s.live_simulations, [] {
      return SettingInfo{"K (OnboardPipeline<Scalar, K>)", "simulations",
                         "live simulations at once; the per-sample cost grows with it. The interface's "
                         "K = 8, at which every footprint is measured"};
    });
    v(s.history_samples, [] {
      return SettingInfo{"OnboardPipeline::history_samples", "samples",
                         "the samples held back: a release is confirmed and dated back within them. On "
                         "tests/host/test_release_detection.cpp 28 changed one row of the real-hand "
                         "table (23 releases in contact, not 21) and 24 dated a release early; a power "
                         "of two keeps the ring index a mask (28 cost 49 instructions per sample on the "
                         "STM32F405)"};
    });
    v(s.release_window_blocks, [] {
      return SettingInfo{"ReleaseWindow::ring_blocks", "blocks",
                         "blocks the release window holds: 2 window_us / block_us + 2, derived from their "
                         "defaults (a static_assert); 10 lost 1-4 % of releases within -10...+20 ms in "
                         "every row of the real-hand table"};
    });
  }
};

// A pipeline's build constants with K live simulations.
constexpr OnboardBuildConstants onboard_build_constants(int live_simulations) {
  return {static_cast<std::uint16_t>(live_simulations), static_cast<std::uint16_t>(onboard_history_samples),
          static_cast<std::uint16_t>(ReleaseWindow<float>::ring_blocks)};
}

template <typename Scalar>
struct FlightResult {
  std::uint32_t flight_number = 0;  // 0, 1, ... in the recording
  std::uint64_t release_us = 0;
  std::uint64_t landing_us = 0;
  bool landed = false;        // false: the recording ended or broke off while airborne
  std::uint32_t samples = 0;  // airborne samples fed to the check
  std::uint32_t gaps = 0;
  std::uint32_t clipped_samples = 0;
  Vec3<Scalar> imu_position_m = Vec3<Scalar>::Zero();
  bool imu_position_estimated = false;
  bool turned = false;  // false: too little rotation to say anything about the tensor (a drop)
  DeviationStats<Scalar> overall;
  Scalar turn_angle_rad = Scalar(0);          // integral of |w| over the flight
  Scalar lever_arm_fit_rms_m_s2 = Scalar(0);  // rms of |a - K r| over the flight with the reported r
  // The flight's first seeded simulations (the first run of the check: before any gap
  // that restarted it), for its flight record.
  SeedSummary<Scalar> first_seeds[kept_first_seeds] = {};
  std::uint32_t first_seed_count = 0;
  TensorEstimate<Scalar> tensor;  // the tensor the flight itself shows (aloft/onboard/tensor_estimator.hpp)
};

// Whether a pipeline takes a rotor whose speed comes with the samples (SPEC §2 rotor,
// ImuSample::rotor_rad_s). A firmware whose body has none builds RotorSupport::none: it
// keeps no speeds in its history and ignores settings.rotor.
enum class RotorSupport : std::uint8_t { none, speed_with_samples };
// Whether a pipeline estimates the tensor each flight shows (FlightResult::tensor); off only
// to measure what the estimate costs (docs/firmware.md).
enum class TensorEstimation : std::uint8_t { off, on };

template <typename Scalar, int K, RotorSupport R = RotorSupport::speed_with_samples,
          TensorEstimation T = TensorEstimation::on>
class OnboardPipeline {
 public:
  static constexpr int history_samples = onboard_history_samples;
  static constexpr bool takes_rotor = R == RotorSupport::speed_with_samples;
  static constexpr bool estimates_tensor = T == TensorEstimation::on;
  using TorqueTest = std::conditional_t<takes_rotor, GyrostatTorqueTest<Scalar, onboard_history_samples>,
                                        BodyTorqueTest<Scalar>>;

  ALOFT_COLD OnboardPipeline(const InertiaTensor<Scalar>& inertia,
                             const OnboardPipelineSettings<Scalar>& settings)
      : OnboardPipeline([&inertia] { return inertia; }, [&settings] { return settings; }) {}
  // The same with the tensor and the settings made in place, by make_inertia() and
  // make_settings() (callables that return them): a firmware's set-up neither builds them on
  // its own frame nor copies them (the STM32F405 image: 448 B of flash less).
  template <
      typename MakeInertia, typename MakeSettings,
      typename = std::enable_if_t<std::is_invocable_r_v<InertiaTensor<Scalar>, MakeInertia&> &&
                                  std::is_invocable_r_v<OnboardPipelineSettings<Scalar>, MakeSettings&>>>
  ALOFT_COLD OnboardPipeline(MakeInertia make_inertia, MakeSettings make_settings)
      : inertia_(make_inertia()),
        settings_(make_settings()),
        sensor_to_body_(settings_.check.sensor_to_body.normalized().toRotationMatrix()),
        sensor_is_body_(sensor_to_body_ == Mat3<Scalar>::Identity()),
        clock_(settings_.clock),
        detector_(settings_.release, torque_test()),
        window_(settings_.release_window),
        lever_arm_(settings_.lever_arm, {settings_.release.ridge_rad_s2, settings_.release.max_lever_arm_m,
                                         settings_.release.free_flight.accel_floor_m_s2}) {}
  // The parts hold references to settings_ and inertia_: a copy would point into this one.
  OnboardPipeline(const OnboardPipeline&) = delete;
  OnboardPipeline& operator=(const OnboardPipeline&) = delete;

  // One sample. Returns ok, or an error status (non-finite numbers, a time stamp not
  // after the previous one) in which case the sample is not used and nothing changes.
  Status push(const ImuSample<Scalar>& sample) {
    if (!all_finite(sample.gyro_rad_s, sample.accel_m_s2)) return Status::non_finite_input;
    const std::uint64_t previous_t_us = clock_.last_t_us();
    const StreamTick tick = clock_.tick(sample);
    if (tick.status != Status::ok) return tick.status;
    if (check_ && tick.gap && tick.dt_us > settings_.end_flight_after_gap_us) {
      feed_until(history_.count());
      end_flight(false, previous_t_us);
    }
    std::uint8_t flags = static_cast<std::uint8_t>(sample.flags | (tick.gap ? imu_gap_before : 0));
    Vec3<Scalar> gyro = sample.gyro_rad_s, accel = sample.accel_m_s2;
    if (!sensor_is_body_) {
      gyro = sensor_to_body_ * gyro;
      accel = sensor_to_body_ * accel;
      // Numbers near the float range's end can overflow in the rotation: no measurement
      // then (the check takes the history's samples as finite).
      if (!all_finite(gyro, accel))
        flags = static_cast<std::uint8_t>(flags | imu_gyro_clipped | imu_accel_clipped);
    }
    speeds_.set(history_.count(), sample.rotor_rad_s, (sample.flags & imu_rotor_speed) != 0);
    history_.push(sample.t_us, gyro, accel, flags);
    if (history_.count() > clock_.half_span()) detect(history_.count() - 1 - clock_.half_span());
    return Status::ok;
  }

  // The recording ended: an open flight ends unlanded.
  ALOFT_COLD void finish() {
    if (!check_) return;
    feed_until(detector_.pending_from(history_.count() - 1));
    end_flight(false, clock_.last_t_us());
  }

  // Moves out the flight that ended since the last call; false when none has.
  bool take_finished_flight(FlightResult<Scalar>& out) {
    const FlightResult<Scalar>* finished = finished_flight();
    if (finished == nullptr) return false;
    out = *finished;
    release_finished_flight();
    return true;
  }
  // The same without a copy (a firmware's stack): the flight that ended, or null; valid
  // until release_finished_flight(), which says it was taken (no new flight starts before).
  // Its tensor estimate is solved here, on the first call: outside push, so that a
  // firmware can take the flight after its burst of samples, off the deepest stack.
  const FlightResult<Scalar>* finished_flight() {
    if (!finished_) return nullptr;
    if (tensor_pending_) solve_tensor_estimate();
    return &current_;
  }
  void release_finished_flight() { finished_ = false; }

  const OnboardPipelineSettings<Scalar>& settings() const { return settings_; }
  const StreamCounts& stream() const { return clock_.counts(); }
  bool airborne() const { return check_.has_value(); }
  // The lever arm the recording's flights have given so far (valid when has_estimate()).
  bool has_imu_position_estimate() const { return lever_arm_.has_estimate(); }
  const Vec3<Scalar>& imu_position_estimate() const { return lever_arm_.estimate(); }
  // The lever arm the open flight's landing is looked for with (while airborne()).
  const Vec3<Scalar>& flight_lever_arm() const { return r_flight_; }

 private:
  // The detector's torque test: with rotor support, the rotor's known torque is part of the
  // model wherever the settings give a rotor (aloft/onboard/torque_test.hpp). Called while
  // constructing: it only takes the addresses of settings_, inertia_ and speeds_.
  TorqueTest torque_test() const {
    if constexpr (takes_rotor) {
      return TorqueTest(settings_.release.free_flight, inertia_, settings_.rotor, speeds_);
    } else {
      return TorqueTest(settings_.release.free_flight, inertia_.tensor());
    }
  }

  // The lever arm to look for a release with: given, else the recording's estimate, else none.
  const Vec3<Scalar>* known_r() const {
    return settings_.imu_position_known ? &settings_.imu_position_m
           : lever_arm_.has_estimate()  ? &lever_arm_.estimate()
                                        : nullptr;
  }

  void detect(std::uint32_t c) {
    if (check_) {
      detect_airborne(c);
    } else {
      detect_on_ground(c);
    }
  }

  // Out of line, each with only its own locals: the frame under the release window's
  // dating and the flight's end is small (footprint.json's worst-case stack).
  ALOFT_OUT_OF_LINE void detect_airborne(std::uint32_t c) {
    const FoundLanding landing =
        detector_.find_landing(history_, c, clock_.half_span(), r_flight_, next_feed_);
    const bool dating = on_probation_ || look_again_;
    if (dating) add_to_window(c);
    if (landing.found) {
      feed_until(landing.index);
      end_flight(true, landing.landing_us);
      return;
    }
    if (dating && !date_release_over_window()) return;
    // Held back a few samples, so a landing can still be dated back over them.
    const std::uint32_t lag = settings_.feed_lag_samples;
    const std::uint32_t held_back = c + 1 > lag ? c + 1 - lag : 0u;
    const std::uint32_t pending = detector_.pending_from(c);
    feed_until(pending < held_back ? pending : held_back);
  }

  ALOFT_OUT_OF_LINE void detect_on_ground(std::uint32_t c) {
    const FoundRelease<Scalar> release =
        detector_.find_release(history_, c, clock_.half_span(), known_r(), rearmed_at_us_);
    add_to_window(c);
    if (!release.found) return;
    // The last flight is not taken yet: it is never overwritten. A firmware takes it after
    // its burst of samples (port/stm32f405/firmware/main.cpp); after a landing no flight
    // starts within rearm_after_landing_us anyway.
    if (finished_) return;
    r_flight_ = release.r;
    on_probation_ = true;
    // A known r that missed this release (the detector fitted one near it) is no better
    // than none: the flight's own fit takes over as soon as it would without one.
    start_flight(release.index, release.release_us, release.r_fitted);
    feed_until(c + 1);
  }

  // Sample c, as the detector has just tested it, joins the window while a release is
  // looked for or on probation (the window needs nothing else).
  void add_to_window(std::uint32_t c) {
    const auto& tested = detector_.newest_tested();
    if (tested.valid) window_.add(c, history_.t_us(c), tested.k, tested.torque_free);
  }

  // The proposed release, once the window has seen enough: kept, dated anew (the check
  // starts again from there, as far as the history still holds it), or withdrawn; and where
  // the window's fit was not settled, looked at once more. False when the flight was withdrawn.
  ALOFT_COLD bool date_release_over_window() {
    const Vec3<Scalar>* known = known_r();
    LeverArmBall<Scalar> ball;
    ball.centre = known != nullptr ? *known : Vec3<Scalar>::Zero();
    ball.radius_m =
        known != nullptr ? settings_.release.given_r_tolerance_m : settings_.release.max_lever_arm_m;
    ball.otherwise = r_flight_;
    ball.ridge_rad_s2 = settings_.release.ridge_rad_s2;
    const bool later_look = look_again_;
    // The window tests each block's torque against the body's tensor where no rotor turned
    // in it: a turning rotor's torque is not in the blocks' sums.
    const bool rotor_turned = rotor_present() && speeds_.turned_since(window_.oldest_index());
    const Mat3<Scalar>* torque_tensor = rotor_turned ? nullptr : &inertia_.tensor();
    const WindowedRelease<Scalar> w = window_.date(release_index_, current_.release_us, ball, later_look,
                                                   torque_tensor, later_look && moved_by_window_);
    if (!w.decided) return true;
    if (later_look) {
      // It only ever dates the release later, past a push the first look took for flight,
      // and only from a settled fit of its own (an r fitted 40 ms on can drift by
      // millimetres: on real hands without a given r, moves past no push).
      look_again_ = false;
      if (w.free && w.settled && w.release_us > current_.release_us) redate_release(w);
      return true;
    }
    on_probation_ = false;
    if (!w.free) {
      check_.reset();
      detector_.reset();
      rearmed_at_us_ = current_.release_us + 1u;
      return false;
    }
    look_again_ = !w.settled;
    moved_by_window_ = w.release_us != current_.release_us;
    if (moved_by_window_) redate_release(w);
    return true;
  }

  // The flight starts again at the window's release (as far as the history still holds it).
  ALOFT_COLD void redate_release(const WindowedRelease<Scalar>& w) {
    const std::uint32_t fed_to = next_feed_;
    const std::uint32_t oldest = history_.oldest();
    start_flight(w.index > oldest ? w.index : oldest, w.release_us, release_missed_given_r_);
    feed_until(fed_to);
  }

  ALOFT_COLD void start_flight(std::uint32_t release, std::uint64_t release_us, bool release_missed_given_r) {
    start_check();
    // Made in place: assigning a new FlightResult put a 120 B temporary on this frame,
    // under the release window's dating (trivially destructible, so nothing is lost).
    ::new (static_cast<void*>(&current_)) FlightResult<Scalar>();
    current_.release_us = release_us;
    next_feed_ = release;
    release_index_ = release;
    release_missed_given_r_ = release_missed_given_r;
    lever_arm_.start_flight(release_missed_given_r);
    tensor_.start();
    tensor_pending_ = false;
  }

  // Feeds the check every sample before index `end` not fed yet.
  void feed_until(std::uint32_t end) {
    for (; next_feed_ < end; ++next_feed_) {
      if (history_.holds(next_feed_)) {
        feed(next_feed_);
      } else {
        tensor_.interrupt();
      }
    }
  }

  void feed(std::uint32_t i) {
    const bool first = i == release_index_;
    const std::uint32_t dt_us = first ? 0u : history_.dt_us(i);
    const std::uint8_t flags = history_.flags(i);
    if (!first && (flags & imu_gap_before) != 0) {
      ++current_.gaps;
      if (dt_us > settings_.bridge_gap_up_to_us) restart_check();
    }
    if ((flags & (imu_gyro_clipped | imu_accel_clipped)) != 0) ++current_.clipped_samples;
    const Scalar dt = static_cast<Scalar>(dt_us) * Scalar(1e-6);
    if ((flags & imu_gyro_clipped) != 0) {
      (void)check_->skip(dt);
      tensor_.interrupt();
      return;
    }
    if (check_->update_finite(history_.gyro(i), dt) == Status::ok) ++current_.samples;
    current_.turn_angle_rad += history_.gyro(i).norm() * dt;
    estimate_sample(i, dt_us, flags);
    fit_sample(i);
  }

  // The tensor estimate takes the sample unless the samples broke before it (a gap) or the
  // rotor's speed is missing where a rotor is.
  void estimate_sample(std::uint32_t i, std::uint32_t dt_us, std::uint8_t flags) {
    const bool rotor = rotor_present();
    const bool no_speed = rotor && (flags & imu_rotor_speed) == 0;
    if ((flags & imu_gap_before) != 0 || no_speed || !history_.holds(i - 1)) tensor_.interrupt();
    if (no_speed) return;
    tensor_.add(history_.gyro(i), history_.gyro(i - 1), rotor ? speeds_.get(i) : Scalar(0), dt_us,
                tensor_inputs());
  }

  bool rotor_present() const { return takes_rotor && settings_.rotor.present(); }
  TensorEstimatorInputs<Scalar> tensor_inputs() const {
    // Without rotor support every speed is 0, so a rotor in the settings adds nothing.
    return {settings_.tensor, inertia_, settings_.rotor};
  }
  ALOFT_COLD void solve_tensor_estimate() {
    tensor_.finish(tensor_inputs(), current_.tensor);
    tensor_pending_ = false;
  }

  // The lever-arm fit takes the samples the gyro calls torque-free.
  void fit_sample(std::uint32_t i) {
    const std::uint32_t h = clock_.half_span();
    BodyKinematics<Scalar> k{typename BodyKinematics<Scalar>::Unset{}};
    if (!history_.kinematics(i, h, k) || !detector_.torque_free_remembered(history_, i, h, k)) return;
    const bool due = lever_arm_.add(LeverArmTerms<Scalar>(k));
    if (due || (on_probation_ && lever_arm_.taken_over())) r_flight_ = flight_r_near_given();
  }

  // The flight's own fit of r, kept within given_r_tolerance_m of a given r that found the
  // release: the ball the detector and the release window fit in. A slowly turning flight
  // fixes r poorly, and its fit can take up an accelerometer's bias: a rotor throw at 4
  // rad/s fitted r 30 mm off the given one, and its flight ended 427 ms early at the
  // rotor's brake. Kept on the ball's surface, not at the given r, so the fit still takes up
  // what the given r leaves (a landing 307 ms early on a fresh seed set with the given r
  // itself). Measured on the seed shifts of tests/host/test_release_detection.cpp
  // (docs/validation/release-detection.md, "A body with a rotor").
  Vec3<Scalar> flight_r_near_given() const {
    const Vec3<Scalar> r = lever_arm_.flight_r();
    const Vec3<Scalar> off = r - settings_.imu_position_m;
    const Scalar off_m = off.norm();
    const Scalar within = settings_.release.given_r_tolerance_m;
    if (!settings_.imu_position_known || release_missed_given_r_ || off_m <= within) return r;
    return settings_.imu_position_m + off * (within / off_m);
  }

  // The simulations alive before a long gap cannot be carried across it.
  ALOFT_COLD void restart_check() {
    keep_first_seeds();
    current_.overall.merge(check_->overall());
    start_check();
  }

  ALOFT_COLD void start_check() {
    OnboardCheckSettings<Scalar> check = settings_.check;
    check.sensor_to_body = Quat<Scalar>::Identity();  // the history is in body axes
    check_.emplace(inertia_, check);
  }

  ALOFT_COLD void end_flight(bool landed, std::uint64_t at_us) {
    keep_first_seeds();
    current_.overall.merge(check_->overall());
    check_.reset();
    detector_.reset();
    on_probation_ = false;
    look_again_ = false;
    if (at_us - current_.release_us < settings_.min_flight_us) {
      ++clock_.counts().short_flights_dropped;
      return;
    }
    current_.flight_number = flights_++;
    current_.landed = landed;
    current_.landing_us = at_us;
    current_.turned = current_.turn_angle_rad >= settings_.turned_at_least_rad;
    if (landed) rearmed_at_us_ = at_us + settings_.rearm_after_landing_us;
    report_lever_arm();
    tensor_pending_ = estimates_tensor;
    finished_ = true;
  }

  // From the check's first run that started any seed.
  ALOFT_COLD void keep_first_seeds() {
    if (current_.first_seed_count > 0) return;
    for (std::uint32_t n = 0; n < kept_first_seeds && check_->first_seed(n, current_.first_seeds[n]); ++n) {
      current_.first_seed_count = n + 1;
    }
  }

  ALOFT_COLD void report_lever_arm() {
    const Vec3<Scalar>* given = settings_.imu_position_known ? &settings_.imu_position_m : nullptr;
    const LeverArmReport<Scalar> report = lever_arm_.finish_flight(given, current_.turn_angle_rad);
    current_.imu_position_m = report.r;
    current_.imu_position_estimated = report.estimated;
    current_.lever_arm_fit_rms_m_s2 = report.fit_rms_m_s2;
  }

  InertiaTensor<Scalar> inertia_;
  OnboardPipelineSettings<Scalar> settings_;  // the one copy: the parts below hold references
  Mat3<Scalar> sensor_to_body_;
  // The sensor's axes are the body's (the usual mounting): samples are taken as they are,
  // which is what the rotation by the identity gives (but for the sign of a zero), without
  // its 30 instructions per sample.
  bool sensor_is_body_;
  StreamClock<Scalar> clock_;
  SampleHistory<Scalar, history_samples> history_;
  ReleaseDetector<Scalar, history_samples, TorqueTest> detector_;
  ReleaseWindow<Scalar> window_;
  LeverArmEstimator<Scalar> lever_arm_;
  std::optional<OnboardCheck<Scalar, K>> check_;
  std::conditional_t<estimates_tensor, TensorEstimator<Scalar, takes_rotor>,
                     NoTensorEstimator<Scalar, takes_rotor>>
      tensor_;
  FlightResult<Scalar> current_;
  Vec3<Scalar> r_flight_ = Vec3<Scalar>::Zero();  // the lever arm the open flight is judged with
  std::uint64_t rearmed_at_us_ = 0;
  std::uint32_t next_feed_ = 0;
  std::uint32_t release_index_ = 0;
  std::uint32_t flights_ = 0;
  bool release_missed_given_r_ = false;  // the open flight's release was found with a fitted r
  bool on_probation_ = false;            // the release is still to be dated over the window
  bool look_again_ = false;              // dated, but the window looks once more (not settled)
  bool moved_by_window_ = false;         // the window's first look moved the release (dated over blocks)
  bool finished_ = false;
  bool tensor_pending_ = false;  // the finished flight's tensor estimate is still to be solved
  // Last: without rotor support it holds nothing, and takes one byte beside the flags.
  RotorSpeedHistory<Scalar, history_samples, takes_rotor> speeds_;
};

}  // namespace aloft
