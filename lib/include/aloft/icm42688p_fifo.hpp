// Decoding of ICM-42688-P FIFO packets (packet 3, big-endian, ±16 g, ±2000 °/s, absolute
// time stamps at TMST_RES = 0) into ImuSample: the one decoder that the firmware driver
// (aloft/icm42688p_driver.hpp) and the host's `aloft replay --fifo` share.
//
// What a packet becomes:
//   - accel: raw / 2048 g, times 9.80665 m/s² per g; gyro: raw / 16.4 °/s, in rad/s.
//     Each is one multiplication of the raw count by a constant rounded once to Scalar,
//     so a given raw count always gives the same Scalar, bit for bit.
//   - a raw value of -32768 on any accel or gyro axis marks the packet invalid (§6): it
//     is dropped (and counted by the caller), its time stamp still moves the clock on.
//   - a raw value at +32767 or -32767 is the end of the range: the sample's
//     imu_accel_clipped / imu_gyro_clipped flag says so.
//   - time: the 16-bit stamps are unwrapped into 64-bit ticks counted from the first
//     valid packet (t = 0). A tick is 1 µs on the PLL or an external clock, 32/30 µs on
//     the internal RC oscillator (§12.7): the clock source is a setting. Consecutive
//     stamps may be at most one wrap (65,536 ticks) apart unless the caller, which knows
//     that data were lost (a FIFO flush), gives an estimate of the elapsed ticks from its
//     own clock: the wrap count is then the one closest to that estimate, and the exact
//     part still comes from the stamps.
//   - gap_before: the stamps moved on by more than 1.5 nominal periods since the last
//     sample returned: packets were lost (a flush) or dropped (invalid). The stamps are
//     exact, so a flush that lost nothing flags nothing.
#pragma once

#include <cstdint>

#include "aloft/icm42688p_registers.hpp"
#include "aloft/imu_sample.hpp"

namespace aloft::icm42688p {

// The clock the chip's time stamps count.
enum class TimestampClock : std::uint8_t {
  pll_or_external,  // nominal: one tick = 1 µs (what `aloft replay --fifo` assumes)
  internal_rc,      // one tick = 32/30 µs (§12.7)
};

// One packet 3 as the bytes hold it, before units.
struct RawPacket3 {
  std::uint8_t header = 0;
  std::int16_t accel[3] = {0, 0, 0};
  std::int16_t gyro[3] = {0, 0, 0};
  std::int8_t temperature = 0;
  std::uint16_t timestamp = 0;
};

inline bool is_packet3_header(std::uint8_t header) { return (header & kPacket3HeaderMask) == kPacket3Header; }

inline std::int16_t big_endian_i16(const std::uint8_t* bytes) {
  return static_cast<std::int16_t>(static_cast<std::uint16_t>((bytes[0] << 8) | bytes[1]));
}

// Reads the 16 bytes at `bytes` as packet 3 (§6 packet structure). The header is not
// checked here.
inline RawPacket3 parse_packet3(const std::uint8_t* bytes) {
  RawPacket3 p;
  p.header = bytes[0];
  for (int axis = 0; axis < 3; ++axis) {
    p.accel[axis] = big_endian_i16(bytes + kPacket3AccelOffset + 2 * axis);
    p.gyro[axis] = big_endian_i16(bytes + kPacket3GyroOffset + 2 * axis);
  }
  p.temperature = static_cast<std::int8_t>(bytes[kPacket3TemperatureOffset]);
  p.timestamp = static_cast<std::uint16_t>(big_endian_i16(bytes + kPacket3TimestampOffset));
  return p;
}

inline bool holds_invalid_value(const RawPacket3& p) {
  for (int axis = 0; axis < 3; ++axis) {
    if (p.accel[axis] == kInvalidSample || p.gyro[axis] == kInvalidSample) return true;
  }
  return false;
}

inline bool at_full_scale(const std::int16_t (&v)[3]) {
  for (int axis = 0; axis < 3; ++axis) {
    if (v[axis] == 32767 || v[axis] == -32767) return true;
  }
  return false;
}

// Units of one count, rounded once to Scalar.
template <typename Scalar>
constexpr Scalar accel_m_s2_per_lsb() {
  return static_cast<Scalar>(kStandardGravity / kAccelLsbPerG);
}
template <typename Scalar>
constexpr Scalar gyro_rad_s_per_lsb() {
  return static_cast<Scalar>(3.14159265358979323846 / 180.0 / kGyroLsbPerDps);
}

enum class PacketOutcome : std::uint8_t {
  sample,          // `out` holds a new sample
  invalid,         // a -32768 packet: dropped, the clock moved on
  foreign_header,  // not packet 3: nothing decoded, no state changed
};

template <typename Scalar>
class FifoDecoder {
 public:
  static constexpr std::uint64_t kStampWrap = 65536;

  // odr_hz: the configured output data rate (sets the 1.5-period gap threshold).
  FifoDecoder(std::uint32_t odr_hz, TimestampClock clock) : clock_(clock) {
    const std::uint64_t period_us = odr_hz > 0 ? 1000000u / odr_hz : 1000u;
    const std::uint64_t period_ticks =
        clock == TimestampClock::internal_rc ? period_us * kRcTickDenominator / kRcTickNumerator : period_us;
    gap_threshold_ticks_ = period_ticks + period_ticks / 2;
  }

  // Data were lost before the next packet (the FIFO was flushed). elapsed_ticks_estimate:
  // the caller's own measure of the ticks from the last packet decoded to the next one,
  // or 0 when it has none (then the stamps alone count, modulo one wrap).
  void expect_gap(std::uint64_t elapsed_ticks_estimate) { elapsed_estimate_ = elapsed_ticks_estimate; }

  PacketOutcome decode(const std::uint8_t* packet, ImuSample<Scalar>& out) {
    if (!is_packet3_header(packet[0])) return PacketOutcome::foreign_header;
    const RawPacket3 raw = parse_packet3(packet);
    const bool valid = !holds_invalid_value(raw);
    // Before the first valid packet there is no time base yet, and nothing to lose.
    if (!started_) {
      if (!valid) return PacketOutcome::invalid;
      start_clock(raw.timestamp);
    } else {
      advance_clock(raw.timestamp);
    }
    if (!valid) return PacketOutcome::invalid;
    out = to_sample(raw);
    if (ticks_ - last_sample_ticks_ > gap_threshold_ticks_) add_flag(out, imu_gap_before);
    last_sample_ticks_ = ticks_;
    return PacketOutcome::sample;
  }

  // Microseconds of the unwrapped tick count (integer, from the count itself: no drift).
  std::uint64_t time_us() const {
    return clock_ == TimestampClock::internal_rc ? ticks_ * kRcTickNumerator / kRcTickDenominator : ticks_;
  }
  bool started() const { return started_; }

 private:
  void start_clock(std::uint16_t stamp) {
    started_ = true;
    elapsed_estimate_ = 0;
    last_stamp_ = stamp;
  }

  static void add_flag(ImuSample<Scalar>& s, ImuSampleFlag flag) {
    s.flags = static_cast<std::uint8_t>(s.flags | flag);
  }

  // Moves the unwrapped clock to `stamp`.
  void advance_clock(std::uint16_t stamp) {
    std::uint64_t delta = static_cast<std::uint16_t>(stamp - last_stamp_);
    if (elapsed_estimate_ > delta) {
      delta += (elapsed_estimate_ - delta + kStampWrap / 2) / kStampWrap * kStampWrap;
    }
    // An equal stamp cannot be the next sample: a whole wrap passed.
    if (delta == 0) delta = kStampWrap;
    elapsed_estimate_ = 0;
    ticks_ += delta;
    last_stamp_ = stamp;
  }

  ImuSample<Scalar> to_sample(const RawPacket3& raw) const {
    ImuSample<Scalar> s;
    s.t_us = time_us();
    for (int axis = 0; axis < 3; ++axis) {
      s.accel_m_s2[axis] = static_cast<Scalar>(raw.accel[axis]) * accel_m_s2_per_lsb<Scalar>();
      s.gyro_rad_s[axis] = static_cast<Scalar>(raw.gyro[axis]) * gyro_rad_s_per_lsb<Scalar>();
    }
    if (at_full_scale(raw.accel)) add_flag(s, imu_accel_clipped);
    if (at_full_scale(raw.gyro)) add_flag(s, imu_gyro_clipped);
    return s;
  }

  TimestampClock clock_;
  bool started_ = false;
  std::uint16_t last_stamp_ = 0;
  std::uint64_t ticks_ = 0;              // since the first valid packet
  std::uint64_t last_sample_ticks_ = 0;  // of the last sample returned
  std::uint64_t elapsed_estimate_ = 0;
  std::uint64_t gap_threshold_ticks_ = 0;
};

}  // namespace aloft::icm42688p
