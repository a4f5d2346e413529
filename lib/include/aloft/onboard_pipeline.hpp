// The onboard pipeline: IMU samples in (aloft/imu_sample.hpp), one result per flight out.
// It is what a firmware runs behind its sensor driver and what `aloft replay` runs on a
// recording, the same code in `float`:
//   samples -> stream accounting (dt from time stamps, gaps, clipping)
//           -> release and landing detection
//           -> the onboard check (aloft/onboard_check.hpp) over the airborne samples
//           -> FlightResult, taken by the caller once the flight has ended.
// A gap longer than `bridge_gap_up_to_us` ends the live simulations (they are seeded anew
// after it); while airborne, a gap longer than `end_flight_after_gap_us` ends the flight
// unlanded. Lost data are counted, never bridged silently.
//
// CONTRACT NOTE (issue 21 work in progress): the public API below is what the replay
// command, the firmware ports and the flight records are written against. The detection
// inside is the core's plain free-fall detector until the spin-aware one replaces it.
#pragma once

#include <cstdint>
#include <optional>

#include "aloft/imu_sample.hpp"
#include "aloft/onboard_check.hpp"

namespace aloft {

template <typename Scalar>
struct OnboardPipelineSettings {
  OnboardCheckSettings<Scalar> check = {};  // seed_every, sensor_to_body
  // The accelerometer's position in body axes from the centre of mass (m), when the body
  // file gives `imu.position`; otherwise it is estimated from the data.
  bool imu_position_known = false;
  Vec3<Scalar> imu_position_m = Vec3<Scalar>::Zero();
  std::uint32_t bridge_gap_up_to_us = 20000;       // longer: live simulations end, seeded anew
  std::uint32_t end_flight_after_gap_us = 200000;  // longer, while airborne: flight ends unlanded
};

// The whole recording so far.
struct StreamCounts {
  std::uint32_t samples = 0;
  std::uint32_t gaps = 0;             // samples flagged imu_gap_before (or stamps far apart)
  std::uint64_t lost_us = 0;          // total length of those gaps
  std::uint32_t clipped_samples = 0;  // samples with a clipped axis
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
};

template <typename Scalar, int K>
class OnboardPipeline {
 public:
  OnboardPipeline(const InertiaTensor<Scalar>& inertia, const OnboardPipelineSettings<Scalar>& settings)
      : inertia_(inertia), settings_(settings) {}

  // One sample. Returns ok, or an error status (non-finite numbers, a time stamp not
  // after the previous one) in which case the sample is not used and nothing changes.
  Status push(const ImuSample<Scalar>& sample) {
    if (!all_finite(sample.gyro_rad_s) || !all_finite(sample.accel_m_s2)) return Status::non_finite_input;
    if (stream_.samples > 0 && sample.t_us <= last_t_us_) return Status::time_not_increasing;
    const bool gap = stream_.samples > 0 && sample.gap_before();
    const std::uint64_t dt_us = stream_.samples > 0 ? sample.t_us - last_t_us_ : 0;
    count(sample, gap, dt_us);
    if (check_ && gap && dt_us > settings_.end_flight_after_gap_us) end_flight(false, last_t_us_);
    if (!check_) start_flight_if_released(sample);
    if (check_) feed(sample, gap, dt_us);
    last_t_us_ = sample.t_us;
    return Status::ok;
  }

  // The recording ended: an open flight ends unlanded.
  void finish() {
    if (check_) end_flight(false, last_t_us_);
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

 private:
  void count(const ImuSample<Scalar>& sample, bool gap, std::uint64_t dt_us) {
    ++stream_.samples;
    if (gap) {
      ++stream_.gaps;
      stream_.lost_us += dt_us;
    }
    if (sample.clipped()) ++stream_.clipped_samples;
  }

  void start_flight_if_released(const ImuSample<Scalar>& sample) {
    if (detector_.update(sample.accel_m_s2) != FlightPhase::airborne) return;
    check_.emplace(inertia_, settings_.check);
    current_ = FlightResult<Scalar>();
    current_.flight_number = flights_++;
    current_.release_us = sample.t_us;
    current_.imu_position_m = settings_.imu_position_m;
    current_.imu_position_estimated = !settings_.imu_position_known;
    max_rate_ = Scalar(0);
    first_ = true;
  }

  void feed(const ImuSample<Scalar>& sample, bool gap, std::uint64_t dt_us) {
    if (gap && !first_) {
      ++current_.gaps;
      if (dt_us > settings_.bridge_gap_up_to_us) restart_check();
    }
    if (sample.clipped()) ++current_.clipped_samples;
    const Scalar dt = first_ ? Scalar(0) : static_cast<Scalar>(dt_us) * Scalar(1e-6);
    const Status s = check_->update(sample.gyro_rad_s, sample.accel_m_s2, dt);
    first_ = false;
    if (s == Status::ok) {
      ++current_.samples;
      const Scalar rate = sample.gyro_rad_s.norm();
      if (rate > max_rate_) max_rate_ = rate;
    }
    if (check_->phase() == FlightPhase::landed) end_flight(true, sample.t_us);
  }

  // The simulations alive before a long gap cannot be carried across it.
  void restart_check() {
    current_.overall.merge(check_->overall());
    check_.emplace(inertia_, settings_.check);
  }

  void end_flight(bool landed, std::uint64_t at_us) {
    current_.overall.merge(check_->overall());
    current_.landed = landed;
    current_.landing_us = at_us;
    current_.turned = max_rate_ > Scalar(0.5);
    finished_ = true;
    check_.reset();
    detector_.reset();
  }

  InertiaTensor<Scalar> inertia_;
  OnboardPipelineSettings<Scalar> settings_;
  FlightDetector<Scalar> detector_{settings_.check.flight};
  std::optional<OnboardCheck<Scalar, K>> check_;
  FlightResult<Scalar> current_;
  StreamCounts stream_;
  std::uint64_t last_t_us_ = 0;
  std::uint32_t flights_ = 0;
  Scalar max_rate_ = Scalar(0);
  bool first_ = true;
  bool finished_ = false;
};

}  // namespace aloft
