// The onboard pipeline: IMU samples in (aloft/imu_sample.hpp), one result per flight out.
// It is what a firmware runs behind its sensor driver and what `aloft replay` runs on a
// recording, the same code in `float`:
//   samples -> stream accounting (dt from time stamps, gaps, clipping), sensor -> body axes
//           -> the last 32 samples (aloft/sample_history.hpp)
//           -> release and landing of a spinning, off-centre IMU (aloft/release_detector.hpp),
//              the release dated anew over a window (aloft/release_window.hpp)
//           -> the onboard check (aloft/onboard_check.hpp) over the airborne samples, fed
//              from the history from the (dated back) release on, never past the landing
//           -> FlightResult, taken by the caller once the flight has ended.
// Gaps: a sample flagged imu_gap_before, or whose stamp is more than `gap_interval_factor`
// running sample intervals after the previous one, starts a gap; gaps are counted, never
// bridged silently. A gap longer than `bridge_gap_up_to_us` ends the live simulations
// (they are seeded anew after it); while airborne, a gap longer than
// `end_flight_after_gap_us` ends the flight unlanded. A clipped gyro sample is not a
// measurement: it is neither compared nor used for detection.
// The accelerometer's position r: from the settings (`imu_position_known`), else fitted
// over each flight's free-flight samples (aloft/lever_arm_estimate.hpp); a flight's fit
// that turned at least `estimate_min_turn_rad`, leaves an rms residual below the
// free-flight floor and agrees between its two halves joins the recording's estimate,
// which the following flights then use like a known r.
#pragma once

#include <cstdint>
#include <optional>

#include "aloft/cold_path.hpp"
#include "aloft/imu_sample.hpp"
#include "aloft/onboard_check.hpp"
#include "aloft/release_detector.hpp"
#include "aloft/release_window.hpp"
#include "aloft/whole_microseconds.hpp"

namespace aloft {

template <typename Scalar>
struct OnboardPipelineSettings {
  OnboardCheckSettings<Scalar> check = {};  // seed_every, sensor_to_body (gyro and accelerometer)
  // The accelerometer's position in body axes from the centre of mass (m), when the body
  // file gives `imu.position`; otherwise it is estimated from the data.
  bool imu_position_known = false;
  Vec3<Scalar> imu_position_m = Vec3<Scalar>::Zero();
  std::uint32_t bridge_gap_up_to_us = 20000;       // longer: live simulations end, seeded anew
  std::uint32_t end_flight_after_gap_us = 200000;  // longer, while airborne: flight ends unlanded
  ReleaseDetectorSettings<Scalar> release = {};
  ReleaseWindowSettings<Scalar> release_window = {};
  Scalar gap_interval_factor = Scalar(3);         // stamps this many running intervals apart: a gap
  std::uint32_t min_flight_us = 100000;           // shorter flights are dropped (a jolt, not a throw)
  std::uint32_t rearm_after_landing_us = 300000;  // no release this soon after a landing (bounces)
  Scalar turned_at_least_rad = Scalar(0.5);       // FlightResult::turned
  Scalar estimate_min_turn_rad = Scalar(2);       // a flight's r fit joins the estimate past this turn
};

// The whole recording so far.
struct StreamCounts {
  std::uint32_t samples = 0;
  std::uint32_t gaps = 0;                   // samples flagged imu_gap_before (or stamps far apart)
  std::uint64_t lost_us = 0;                // total length of those gaps
  std::uint32_t clipped_samples = 0;        // samples with a clipped axis
  std::uint32_t short_flights_dropped = 0;  // free flight shorter than min_flight_us
};

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
};

template <typename Scalar, int K>
class OnboardPipeline {
 public:
  static constexpr int history_samples = 32;
  static constexpr std::uint32_t feed_lag_samples = 8;

  OnboardPipeline(const InertiaTensor<Scalar>& inertia, const OnboardPipelineSettings<Scalar>& settings)
      : inertia_(inertia),
        settings_(settings),
        sensor_to_body_(settings.check.sensor_to_body.normalized().toRotationMatrix()),
        detector_(settings.release, inertia.tensor()),
        window_(settings.release_window) {
    check_settings_ = settings.check;
    check_settings_.sensor_to_body = Quat<Scalar>::Identity();  // the history is in body axes
  }

  // One sample. Returns ok, or an error status (non-finite numbers, a time stamp not
  // after the previous one) in which case the sample is not used and nothing changes.
  Status push(const ImuSample<Scalar>& sample) {
    if (!all_finite(sample.gyro_rad_s) || !all_finite(sample.accel_m_s2)) return Status::non_finite_input;
    if (stream_.samples > 0 && sample.t_us <= last_t_us_) return Status::time_not_increasing;
    const std::uint64_t dt_us = stream_.samples > 0 ? sample.t_us - last_t_us_ : 0;
    const bool gap = stream_.samples > 0 && (sample.gap_before() || stamps_far_apart(dt_us));
    count(sample, gap, dt_us);
    if (check_ && gap && dt_us > settings_.end_flight_after_gap_us) {
      feed_until(history_.count());
      end_flight(false, last_t_us_);
    }
    const std::uint8_t flags = static_cast<std::uint8_t>(sample.flags | (gap ? imu_gap_before : 0));
    history_.push(sample.t_us, sensor_to_body_ * sample.gyro_rad_s, sensor_to_body_ * sample.accel_m_s2,
                  flags);
    if (!gap && dt_us > 0) track_interval(dt_us);
    last_t_us_ = sample.t_us;
    if (history_.count() > half_span_) detect(history_.count() - 1 - half_span_);
    return Status::ok;
  }

  // The recording ended: an open flight ends unlanded.
  ALOFT_COLD void finish() {
    if (!check_) return;
    feed_until(detector_.pending_from(history_.count() - 1));
    end_flight(false, last_t_us_);
  }

  // Moves out the flight that ended since the last call; false when none has.
  bool take_finished_flight(FlightResult<Scalar>& out) {
    if (!finished_) return false;
    out = current_;
    finished_ = false;
    return true;
  }

  const StreamCounts& stream() const { return stream_; }
  bool airborne() const { return check_.has_value(); }
  // The lever arm the recording's flights have given so far (valid when has_estimate()).
  bool has_imu_position_estimate() const { return have_estimate_; }
  const Vec3<Scalar>& imu_position_estimate() const { return r_estimate_; }

 private:
  void count(const ImuSample<Scalar>& sample, bool gap, std::uint64_t dt_us) {
    ++stream_.samples;
    if (gap) {
      ++stream_.gaps;
      stream_.lost_us += dt_us;
    }
    if (sample.clipped()) ++stream_.clipped_samples;
  }

  bool stamps_far_apart(std::uint64_t dt_us) const {
    return interval_us_ > Scalar(0) &&
           scalar_of_us<Scalar>(dt_us) > settings_.gap_interval_factor * interval_us_;
  }

  // Running sample interval (µs) and the half span h of the w_dot difference in samples.
  void track_interval(std::uint64_t dt_us) {
    const Scalar dt = scalar_of_us<Scalar>(dt_us);
    interval_us_ = interval_us_ > Scalar(0) ? interval_us_ + (dt - interval_us_) / Scalar(16) : dt;
    const Scalar span = static_cast<Scalar>(settings_.release.derivative_half_span_us) / interval_us_;
    half_span_ = span < Scalar(1.5) ? 1u
                 : span > Scalar(4) ? 4u
                                    : static_cast<std::uint32_t>(span + Scalar(0.5));
  }

  void detect(std::uint32_t c) {
    if (check_) {
      std::uint32_t landing = 0;
      std::uint64_t landing_us = 0;
      const bool landed =
          detector_.find_landing(history_, c, half_span_, r_flight_, next_feed_, landing, landing_us);
      if (on_probation_) add_to_window(c);
      if (landed) {
        feed_until(landing);
        end_flight(true, landing_us);
        return;
      }
      if (on_probation_ && !date_release_over_window()) return;
      // Held back a few samples, so a landing can still be dated back over them.
      const std::uint32_t held_back = c + 1 > feed_lag_samples ? c + 1 - feed_lag_samples : 0u;
      const std::uint32_t pending = detector_.pending_from(c);
      feed_until(pending < held_back ? pending : held_back);
      return;
    }
    const Vec3<Scalar>* known = settings_.imu_position_known ? &settings_.imu_position_m
                                : have_estimate_             ? &r_estimate_
                                                             : nullptr;
    std::uint32_t release = 0;
    std::uint64_t release_us = 0;
    const bool proposed = detector_.find_release(history_, c, half_span_, known, rearmed_at_us_, release,
                                                 release_us, r_flight_);
    add_to_window(c);
    if (!proposed) return;
    on_probation_ = true;
    // A known r that missed this release (the detector fitted one near it) is no better
    // than none: the flight's own fit takes over as soon as it would without one.
    start_flight(release, release_us, detector_.release_r_fitted());
    feed_until(c + 1);
  }

  // Sample c, as the detector has just tested it, joins the window while a release is
  // looked for or on probation (the window needs nothing else).
  void add_to_window(std::uint32_t c) {
    const auto& tested = detector_.newest_tested();
    if (tested.valid) window_.add(c, history_.t_us(c), tested.k, tested.torque_free);
  }

  // The proposed release, once the window has seen enough: kept, dated anew (the check
  // starts again from there, as far as the history still holds it), or withdrawn. False
  // when the flight was withdrawn.
  ALOFT_COLD bool date_release_over_window() {
    const Vec3<Scalar>* known = settings_.imu_position_known ? &settings_.imu_position_m
                                : have_estimate_             ? &r_estimate_
                                                             : nullptr;
    LeverArmBall<Scalar> ball;
    ball.centre = known != nullptr ? *known : Vec3<Scalar>::Zero();
    ball.radius_m =
        known != nullptr ? settings_.release.given_r_tolerance_m : settings_.release.max_lever_arm_m;
    ball.otherwise = r_flight_;
    ball.ridge_rad_s2 = settings_.release.ridge_rad_s2;
    const WindowedRelease<Scalar> w = window_.date(release_index_, current_.release_us, ball);
    if (!w.decided) return true;
    on_probation_ = false;
    if (!w.free) {
      check_.reset();
      detector_.reset();
      rearmed_at_us_ = current_.release_us + 1u;
      return false;
    }
    if (w.release_us != current_.release_us) {
      const std::uint32_t fed_to = next_feed_;
      const std::uint32_t oldest = history_.oldest();
      start_flight(w.index > oldest ? w.index : oldest, w.release_us, fit_r_in_flight_);
      feed_until(fed_to);
    }
    return true;
  }

  ALOFT_COLD void start_flight(std::uint32_t release, std::uint64_t release_us, bool fit_r_in_flight) {
    check_.emplace(inertia_, check_settings_);
    current_ = FlightResult<Scalar>();
    current_.release_us = release_us;
    next_feed_ = release;
    release_index_ = release;
    fit_r_in_flight_ = fit_r_in_flight;
    flight_fit_.reset();
    half_fit_[0].reset();
    half_fit_[1].reset();
  }

  // Feeds the check every sample before index `end` not fed yet.
  void feed_until(std::uint32_t end) {
    for (; next_feed_ < end; ++next_feed_) {
      if (history_.holds(next_feed_)) feed(next_feed_);
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
      return;
    }
    if (check_->update(history_.gyro(i), dt) == Status::ok) ++current_.samples;
    current_.turn_angle_rad += history_.gyro(i).norm() * dt;
    fit_sample(i);
  }

  // The lever-arm fit takes the samples the gyro calls torque-free.
  void fit_sample(std::uint32_t i) {
    BodyKinematics<Scalar> k;
    if (!history_.kinematics(i, half_span_, k) || !detector_.torque_free_remembered(i, half_span_, k)) return;
    const LeverArmTerms<Scalar> terms(k);
    flight_fit_.add(terms);
    half_fit_[(flight_fit_.count() / 16u) % 2u].add(terms);
    // A given or earlier r gives way to this flight's own fit once it has seen enough.
    const std::uint32_t enough = fit_r_in_flight_ ? 8u : 64u;
    if (flight_fit_.count() >= enough) r_flight_ = flight_fit_.solve(settings_.release.ridge_rad_s2);
  }

  // The simulations alive before a long gap cannot be carried across it.
  ALOFT_COLD void restart_check() {
    keep_first_seeds();
    current_.overall.merge(check_->overall());
    check_.emplace(inertia_, check_settings_);
  }

  ALOFT_COLD void end_flight(bool landed, std::uint64_t at_us) {
    keep_first_seeds();
    current_.overall.merge(check_->overall());
    check_.reset();
    detector_.reset();
    on_probation_ = false;
    if (at_us - current_.release_us < settings_.min_flight_us) {
      ++stream_.short_flights_dropped;
      return;
    }
    current_.flight_number = flights_++;
    current_.landed = landed;
    current_.landing_us = at_us;
    current_.turned = current_.turn_angle_rad >= settings_.turned_at_least_rad;
    if (landed) rearmed_at_us_ = at_us + settings_.rearm_after_landing_us;
    report_lever_arm();
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
    if (settings_.imu_position_known) {
      current_.imu_position_m = settings_.imu_position_m;
      current_.lever_arm_fit_rms_m_s2 = flight_fit_.rms_residual(settings_.imu_position_m);
      return;
    }
    const Scalar ridge = settings_.release.ridge_rad_s2;
    const Vec3<Scalar> r = flight_fit_.solve(ridge);
    const Scalar rms = flight_fit_.rms_residual(r);
    const Vec3<Scalar> ra = half_fit_[0].solve(ridge);
    const Vec3<Scalar> rb = half_fit_[1].solve(ridge);
    const Scalar agree = Scalar(0.005) + Scalar(0.25) * r.norm();
    if (current_.turn_angle_rad >= settings_.estimate_min_turn_rad &&
        r.norm() <= settings_.release.max_lever_arm_m &&
        rms <= settings_.release.free_flight.accel_floor_m_s2 && (ra - rb).norm() <= agree) {
      estimate_fit_.merge(flight_fit_);
      r_estimate_ = estimate_fit_.solve(ridge);
      have_estimate_ = true;
    }
    current_.imu_position_m = have_estimate_ ? r_estimate_ : r;
    current_.imu_position_estimated = true;
    current_.lever_arm_fit_rms_m_s2 = flight_fit_.rms_residual(current_.imu_position_m);
  }

  InertiaTensor<Scalar> inertia_;
  OnboardPipelineSettings<Scalar> settings_;
  OnboardCheckSettings<Scalar> check_settings_;
  Mat3<Scalar> sensor_to_body_;
  SampleHistory<Scalar, history_samples> history_;
  ReleaseDetector<Scalar, history_samples> detector_;
  ReleaseWindow<Scalar> window_;
  std::optional<OnboardCheck<Scalar, K>> check_;
  FlightResult<Scalar> current_;
  StreamCounts stream_;
  LeverArmFit<Scalar> flight_fit_;
  LeverArmFit<Scalar> half_fit_[2];
  LeverArmFit<Scalar> estimate_fit_;
  Vec3<Scalar> r_flight_ = Vec3<Scalar>::Zero();  // the lever arm the open flight is judged with
  Vec3<Scalar> r_estimate_ = Vec3<Scalar>::Zero();
  std::uint64_t last_t_us_ = 0;
  std::uint64_t rearmed_at_us_ = 0;
  Scalar interval_us_ = Scalar(0);
  std::uint32_t half_span_ = 1;
  std::uint32_t next_feed_ = 0;
  std::uint32_t release_index_ = 0;
  std::uint32_t flights_ = 0;
  bool fit_r_in_flight_ = false;
  bool on_probation_ = false;  // the release is still to be dated over the window
  bool have_estimate_ = false;
  bool finished_ = false;
};

}  // namespace aloft
