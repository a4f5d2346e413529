// The last N samples, in body axes, so that a release confirmed a few milliseconds late
// can be dated back to the first free-flight sample and the check fed from there.
// Samples are numbered 0, 1, ... as pushed (their index); the history holds the N
// newest. Each takes 6 floats, the low 32 bits of its stamp and its flags: with N = 32
// and float that is 928 bytes. Angular acceleration comes from a central difference of
// the gyro over +-h samples (h picked from the sample interval, so about the same span in
// time at 100 Hz and at 4 kHz): the noise of a one-sample difference at 4 kHz would
// swamp the lever arm's w_dot x r.
#pragma once

#include <cstdint>

#include "aloft/cold_path.hpp"
#include "aloft/dynamics/free_flight_residual.hpp"
#include "aloft/dynamics/rotor.hpp"
#include "aloft/sensor/imu_sample.hpp"

namespace aloft {

template <typename Scalar, int N>
class SampleHistory {
  static_assert(N >= 8, "room for a central difference and a confirmation window");

 public:
  void push(std::uint64_t t_us, const Vec3<Scalar>& gyro_body, const Vec3<Scalar>& accel_body,
            std::uint8_t flags) {
    Entry& e = entries_[count_ % N];
    e.gyro = gyro_body;
    e.accel = accel_body;
    e.t_low = static_cast<std::uint32_t>(t_us);
    flags_[count_ % N] = flags;
    newest_t_us_ = t_us;
    ++count_;
  }
  void clear() { count_ = 0; }

  std::uint32_t count() const { return count_; }  // samples pushed so far
  bool holds(std::uint32_t i) const { return i < count_ && count_ - i <= static_cast<std::uint32_t>(N); }
  std::uint32_t oldest() const { return count_ > static_cast<std::uint32_t>(N) ? count_ - N : 0; }

  const Vec3<Scalar>& gyro(std::uint32_t i) const { return entries_[i % N].gyro; }
  const Vec3<Scalar>& accel(std::uint32_t i) const { return entries_[i % N].accel; }
  std::uint8_t flags(std::uint32_t i) const { return flags_[i % N]; }
  ALOFT_OUT_OF_LINE std::uint64_t t_us(std::uint32_t i) const {
    return newest_t_us_ - (entries_[(count_ - 1) % N].t_low - entries_[i % N].t_low);
  }
  // Stamp difference from sample a to sample b (µs), both held, a <= b.
  std::uint32_t span_us(std::uint32_t a, std::uint32_t b) const {
    return entries_[b % N].t_low - entries_[a % N].t_low;
  }
  // Stamp difference to the previous sample (µs); 0 for the oldest one held.
  std::uint32_t dt_us(std::uint32_t i) const {
    return holds(i - 1) && i > 0 ? entries_[i % N].t_low - entries_[(i - 1) % N].t_low : 0u;
  }

  // Sample i's rate, angular acceleration (from samples i-h and i+h) and specific force.
  // False when the span is not held, crosses a gap or holds a clipped gyro sample.
  ALOFT_OUT_OF_LINE bool kinematics(std::uint32_t i, std::uint32_t h, BodyKinematics<Scalar>& out) const {
    if (i < h || !holds(i - h) || !holds(i + h)) return false;
    // No clipped gyro in [i - h, i + h], no gap inside it: the flags ORed, tested once.
    unsigned bad = flags_[(i - h) % N] & imu_gyro_clipped;
    for (std::uint32_t j = i - h + 1; j <= i + h; ++j) bad |= flags_[j % N];
    if ((bad & (imu_gyro_clipped | imu_gap_before)) != 0) return false;
    const std::uint32_t span_us = entries_[(i + h) % N].t_low - entries_[(i - h) % N].t_low;
    out.w = gyro(i);
    out.w_dot = (gyro(i + h) - gyro(i - h)) * (Scalar(1e6) / static_cast<Scalar>(span_us));
    out.a = accel(i);
    return true;
  }

 private:
  struct Entry {
    Vec3<Scalar> gyro;   // rad/s, body axes
    Vec3<Scalar> accel;  // m/s², body axes
    std::uint32_t t_low;
  };
  Entry entries_[N] = {};
  std::uint8_t flags_[N] = {};
  std::uint64_t newest_t_us_ = 0;
  std::uint32_t count_ = 0;
};

// A rotor's angular momentum relative to the body at one sample, and its rate (body axes).
template <typename Scalar>
struct RotorMomentum {
  Vec3<Scalar> h;      // kg·m²/s
  Vec3<Scalar> h_dot;  // N·m
};

// The rotor's speed (ImuSample::rotor_rad_s) of the same N samples, by the same index, kept
// only by a pipeline that takes a rotor (RotorSupport): the others hold nothing and read 0.
template <typename Scalar, int N, bool Keep>
class RotorSpeedHistory {
 public:
  // A speed that is not known (no imu_rotor_speed, or not a number) may be any: it counts
  // as turning.
  void set(std::uint32_t i, Scalar speed, bool known) {
    speeds_[i % N] = speed;
    if (!known || !(speed <= Scalar(0) && speed >= Scalar(0))) {
      last_turning_ = i;
      turned_ = true;
    }
  }
  Scalar get(std::uint32_t i) const { return speeds_[i % N]; }
  // Whether the rotor turned at sample i or after (it adds a torque from then on).
  bool turned_since(std::uint32_t i) const { return turned_ && last_turning_ >= i; }

  // The rotor's h at sample i and its rate: a central difference of the speed over the same
  // +-half samples as the gyro's w_dot (SampleHistory::kinematics), so that both sides of
  // Euler's equations are filtered alike. Only where that w_dot was formed (its span held,
  // no gap); false when sample i - half, i or i + half carries no speed (imu_rotor_speed).
  bool momentum(const SampleHistory<Scalar, N>& history, std::uint32_t i, std::uint32_t half,
                const Rotor<Scalar>& rotor, RotorMomentum<Scalar>& out) const {
    const unsigned read = history.flags(i - half) & history.flags(i) & history.flags(i + half);
    if ((read & imu_rotor_speed) == 0) return false;
    const Scalar span_s = static_cast<Scalar>(history.span_us(i - half, i + half)) * Scalar(1e-6);
    out.h = rotor.momentum(get(i));
    out.h_dot = rotor.momentum((get(i + half) - get(i - half)) / span_s);
    return true;
  }

 private:
  Scalar speeds_[N] = {};
  std::uint32_t last_turning_ = 0;
  bool turned_ = false;
};

template <typename Scalar, int N>
class RotorSpeedHistory<Scalar, N, false> {
 public:
  void set(std::uint32_t, Scalar, bool) {}
  Scalar get(std::uint32_t) const { return Scalar(0); }
  bool turned_since(std::uint32_t) const { return false; }
  bool momentum(const SampleHistory<Scalar, N>&, std::uint32_t, std::uint32_t, const Rotor<Scalar>&,
                RotorMomentum<Scalar>&) const {
    return false;
  }
};

}  // namespace aloft
