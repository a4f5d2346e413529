// The onboard check: the seed study's "a simulation from every sampled state", in the
// fixed memory of a firmware. Fed one gyro sample at a time, every one of them airborne
// (the onboard pipeline, aloft/onboard/onboard_pipeline.hpp, finds release and landing on a
// spinning, off-centre IMU and feeds it the samples in between), it
//   - every `seed_every` airborne samples starts a simulation from the measured rate;
//     at most K are alive, and starting one more retires the oldest;
//   - advances every live simulation one step per sample (torque-free body rate, RK4)
//     and compares it with the gyro: DA and relative error, per seed and overall;
//   - keeps the RMS DA and relative error of the flight's first `kept_first_seeds`
//     seeds when they retire: they ran longest, and a flight record stores them
//     (aloft/records/flight_record.hpp).
// Rates are compared as body rates, so no orientation is integrated: a gyro alone
// cannot observe it and the torque-free body rate does not depend on it. The
// simulations live in the tensor's principal axes (Euler's equations with a diagonal
// tensor, aloft/dynamics/principal_dynamics.hpp) and each gyro sample is rotated into them once;
// the deviation angle and relative error do not depend on the axes they are taken in.
// The DA's atan2 is aloft's polynomial (aloft/lanes/lane_angle.hpp), not the C library's
// software atan2f.
#pragma once

#include <cstdint>
#include <limits>

#include "aloft/cold_path.hpp"
#include "aloft/dynamics/deviation.hpp"
#include "aloft/lanes/lane_angle.hpp"
#include "aloft/dynamics/principal_frame.hpp"
#include "aloft/settings.hpp"

namespace aloft {

template <typename Scalar>
struct OnboardCheckSettings {
  std::uint16_t seed_every = 10;  // samples between seeds (N)
  Quat<Scalar> sensor_to_body = Quat<Scalar>::Identity();

  // The one list of these settings (aloft/settings.hpp).
  template <typename Self, typename Visitor>
  static void visit(Self& s, Visitor&& v) {
    v(s.seed_every, [] {
      return SettingInfo{"check.seed_every", "samples",
                         "a simulation is seeded every this many airborne samples (the seed study's N): "
                         "10 ms at 1 kHz, so K = 8 live seeds span the newest 80 ms. Not swept"};
    });
    v(s.sensor_to_body, [] {
      return SettingInfo{"check.sensor_to_body", "quaternion",
                         "sensor to body axes, for gyro and accelerometer; identity when the IMU is "
                         "mounted aligned. A property of the mounting"};
    });
  }
};

// What one seeded simulation has accumulated so far.
template <typename Scalar>
struct SeedReport {
  std::uint32_t seed_number = 0;       // 0 for the first seed of the flight, then 1, 2, ...
  std::uint32_t seeded_at_sample = 0;  // airborne sample index it was seeded from
  bool live = false;
  DeviationStats<Scalar> stats;
};

// One seed's figures once it is no longer held: what a flight record keeps of it.
template <typename Scalar>
struct SeedSummary {
  Scalar rms_da_rad = Scalar(0);
  Scalar rms_rel_err = Scalar(0);
};

constexpr std::uint32_t kept_first_seeds = 4;

template <typename Scalar, int K>
class OnboardCheck {
  static_assert(K >= 1, "at least one live simulation");

 public:
  ALOFT_COLD OnboardCheck(const InertiaTensor<Scalar>& inertia, const OnboardCheckSettings<Scalar>& settings)
      : OnboardCheck(PrincipalFrame<Scalar>(inertia), settings) {}

 private:
  // The principal frame formed once (a firmware's stack holds one, not two).
  OnboardCheck(const PrincipalFrame<Scalar>& frame, const OnboardCheckSettings<Scalar>& settings)
      : coefficients_(frame.coefficients()),
        seed_every_(settings.seed_every > 0 ? settings.seed_every : std::uint16_t{1}),
        sensor_to_principal_(frame.to_body_matrix().transpose() *
                             settings.sensor_to_body.normalized().toRotationMatrix()) {}

 public:
  // One airborne gyro sample (rad/s, sensor axes) taken dt seconds after the previous
  // one (dt is ignored for the very first). Returns ok, or an error status, in which case
  // nothing changes.
  Status update(const Vec3<Scalar>& gyro, Scalar dt) {
    const Status s = all_finite(gyro) ? dt_status(dt, false) : Status::non_finite_input;
    if (s != Status::ok) return s;
    use_sample(gyro, dt);
    return Status::ok;
  }

  // update() for a gyro sample and a dt the caller has already found finite (the onboard
  // pipeline tests every sample as it arrives): the numbers are not tested again (about
  // 20 instructions per sample on a Cortex-M4F). Returns ok or non_positive_time_step.
  Status update_finite(const Vec3<Scalar>& gyro, Scalar dt) {
    const Status s = dt_status(dt, true);
    if (s != Status::ok) return s;
    use_sample(gyro, dt);
    return Status::ok;
  }

  // A sample whose gyro is no measurement (an axis clipped): the live simulations step
  // over its dt, nothing is compared and no seed starts. Returns ok or an error status.
  Status skip(Scalar dt) {
    const Status s = dt_status(dt, false);
    if (s != Status::ok || samples_ == 0) return s;
    step_live(half_step_coefficients(coefficients_, dt));
    return Status::ok;
  }

  std::uint32_t airborne_samples() const { return samples_; }
  std::uint32_t seeds_started() const { return seeds_started_; }
  int live_simulations() const { return live_; }
  // Over every comparison of every simulation, live or retired: the retired ones' figures
  // were merged as they retired, the live ones' are merged here, so no sample pays for
  // an overall running mean besides the per-seed one.
  ALOFT_COLD DeviationStats<Scalar> overall() const {
    DeviationStats<Scalar> all = retired_;
    for (int n = 0; n < live_; ++n) all.merge(stats(slots_[n]));
    return all;
  }
  // Slot i in [0, K): the i-th newest seed still held (live, or the last ones retired).
  SeedReport<Scalar> seed(int i) const {
    const int n = slot_of_newest(i);
    SeedReport<Scalar> out;
    if (n >= live_) return out;  // not used yet
    out.seed_number = slots_[n].seed_number;
    out.seeded_at_sample = slots_[n].seeded_at_sample;
    out.live = true;
    out.stats = stats(slots_[n]);
    return out;
  }
  // Seed n (< kept_first_seeds) as it stands if still held, else as it stood when it
  // retired; false when fewer than n + 1 seeds have started.
  bool first_seed(std::uint32_t n, SeedSummary<Scalar>& out) const {
    if (n >= kept_first_seeds || n >= seeds_started_) return false;
    out = retired_first_[n];
    for (int i = 0; i < live_; ++i) {
      if (slots_[i].seed_number == n) out = summary(stats(slots_[i]));
    }
    return true;
  }

 private:
  // A live simulation. Slots are taken in order and never freed (a new seed takes the
  // oldest's), so the live ones are slots [0, live_): the per-sample loop runs over them
  // without testing each. Its comparisons are kept as sums, not running means, and its
  // count as the check's count of compared samples when it was seeded (every live seed
  // is compared at every compared sample): a sample costs each seed two additions, not a
  // count, a conversion, two subtractions and two divisions. A seed lives K * seed_every
  // samples, so a float sum adds at most that many terms. The relative error is kept
  // squared (its maximum too), which is all its RMS needs.
  struct Slot {
    std::uint32_t seed_number = 0;
    std::uint32_t seeded_at_sample = 0;
    std::uint32_t compared_before = 0;  // compared_ when it was seeded
    LaneVec3<Scalar> omega = {};        // body rate of the simulation, principal axes
    Scalar sum_square_da = Scalar(0);
    Scalar sum_square_rel = Scalar(0);
    Scalar max_da = Scalar(0);
    Scalar max_square_rel = Scalar(0);
  };

  // dt's rule, in one place: the first airborne sample has nothing to step from, so its
  // dt need only be finite; every later one must pass validate_step (finite, > 0).
  // known_finite: the caller has tested it already (a constant where it is inlined).
  Status dt_status(Scalar dt, bool known_finite) const {
    if (samples_ > 0) return known_finite ? validate_finite_step(dt) : validate_step(dt);
    return known_finite || std::isfinite(dt) ? Status::ok : Status::non_finite_input;
  }

  void use_sample(const Vec3<Scalar>& gyro, Scalar dt) {
    const Vec3<Scalar> m = sensor_to_principal_ * gyro;
    const LaneVec3<Scalar> measured{m.x(), m.y(), m.z()};
    const Scalar norm_sq = m.squaredNorm();
    // Common to every seed: each takes the same step.
    const EulerCoefficients<Scalar> half_c = half_step_coefficients(coefficients_, dt);
    // A zero rate has no direction to compare; below the smallest normal number, its
    // square's inverse would overflow (a rate under 1e-19 rad/s in float).
    if (norm_sq >= std::numeric_limits<Scalar>::min()) {
      step_and_compare(half_c, measured, Scalar(1) / norm_sq);
    } else {
      step_live(half_c);
    }
    if (samples_ % seed_every_ == 0) start_seed(measured);
    ++samples_;
  }

  // Every live simulation one step on (half_c: half_step_coefficients of the step).
  // Out of line: rare (a clipped gyro, a zero rate), and one copy of the step for both.
  ALOFT_COLD void step_live(const EulerCoefficients<Scalar>& half_c) {
    for (int n = 0; n < live_; ++n) step(half_c, slots_[n].omega);
  }

  // The same, each compared with the measured rate (inverse_norm_sq: 1 / its squared
  // norm, finite).
  void step_and_compare(const EulerCoefficients<Scalar>& half_c, const LaneVec3<Scalar>& measured,
                        Scalar inverse_norm_sq) {
    for (int n = 0; n < live_; ++n) {
      Slot& slot = slots_[n];
      const LaneVec3<Scalar> w = step(half_c, slot.omega);
      const Scalar da = lane_deviation_angle(w, measured);
      const Scalar dx = w.x - measured.x;
      const Scalar dy = w.y - measured.y;
      const Scalar dz = w.z - measured.z;
      const Scalar square_rel = (dx * dx + dy * dy + dz * dz) * inverse_norm_sq;
      slot.sum_square_da += da * da;
      slot.sum_square_rel += square_rel;
      if (da > slot.max_da) slot.max_da = da;
      if (square_rel > slot.max_square_rel) slot.max_square_rel = square_rel;
    }
    ++compared_;
  }

  // One RK4 step of a simulation's rate, written back in place (whole-vector assignment
  // went through the stack on a Cortex-M4F: six instructions per seed and sample more).
  static LaneVec3<Scalar> step(const EulerCoefficients<Scalar>& half_c, LaneVec3<Scalar>& omega) {
    const LaneVec3<Scalar> w = principal_rate_rk4_half_steps(half_c, omega);
    omega.x = w.x;
    omega.y = w.y;
    omega.z = w.z;
    return w;
  }

  // Out of line (one sample in seed_every): its code is kept out of the per-sample loop.
  ALOFT_COLD void start_seed(const LaneVec3<Scalar>& measured) {
    newest_ = (newest_ + 1) % K;  // the oldest slot, once all K are in use
    Slot& slot = slots_[newest_];
    if (newest_ < live_) {
      retire(slot);
    } else {
      ++live_;
    }
    slot = Slot();
    slot.seed_number = seeds_started_++;
    slot.seeded_at_sample = samples_;
    slot.compared_before = compared_;
    slot.omega = measured;
  }

  // The slot's seed gives way to a new one: its figures join the overall ones, and the
  // flight's first seeds are kept for the record.
  void retire(const Slot& slot) {
    const DeviationStats<Scalar> s = stats(slot);
    retired_.merge(s);
    if (slot.seed_number < kept_first_seeds) retired_first_[slot.seed_number] = summary(s);
  }

  DeviationStats<Scalar> stats(const Slot& slot) const {
    return DeviationStats<Scalar>::from_sums(compared_ - slot.compared_before, slot.sum_square_da,
                                             slot.sum_square_rel, slot.max_da,
                                             std::sqrt(slot.max_square_rel));
  }

  int slot_of_newest(int i) const { return ((newest_ - i) % K + K) % K; }
  static SeedSummary<Scalar> summary(const DeviationStats<Scalar>& stats) {
    return {stats.rms_da(), stats.rms_relative_error()};
  }

  EulerCoefficients<Scalar> coefficients_;
  std::uint16_t seed_every_;  // of the settings (0 taken as 1); the rest is used up front
  Mat3<Scalar> sensor_to_principal_;
  Slot slots_[K] = {};
  SeedSummary<Scalar> retired_first_[kept_first_seeds] = {};
  DeviationStats<Scalar> retired_;  // over the comparisons of every retired seed
  std::uint32_t samples_ = 0;
  std::uint32_t compared_ = 0;  // samples compared (not skipped, not a zero rate)
  std::uint32_t seeds_started_ = 0;
  int newest_ = K - 1;
  int live_ = 0;
};

}  // namespace aloft
