// Decoding of ICM-42688-P FIFO packets (packet 3, big-endian, ±16 g, ±2000 °/s, absolute
// time stamps at TMST_RES = 0) into ImuSample: the one decoder that the firmware driver
// (aloft/sensor/icm42688p_driver.hpp) and the host's `aloft replay --fifo` share.
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
//
// Walking FIFO_DATA bytes (next(): one item at a time; the driver walks each burst, the
// host's `aloft replay --fifo` a whole recording, with this same code):
//   - a packet-3 header (0x68-0x6B) with 16 bytes: a packet (sample or invalid);
//   - the header 0x80 (HEADER_MSG = 1, §6.2 "FIFO is empty"; the other bits clear): an
//     empty read, never an error. The datasheet defines that header; what the rest of a
//     burst read from an empty FIFO holds it does not say (0x80 again, 0x00 or 0xFF are
//     all plausible, and a fixed-size reader records them). A recording holds either the
//     byte alone (a reader that stopped at it) or the whole 16-byte slot (a fixed-size
//     burst). Told apart by the byte after it (empty_read_bytes):
//       the next byte is a packet-3 header       -> the byte alone (1 byte);
//       fewer than 16 bytes left                 -> the byte alone if the next byte is
//                                                   0x80, else a cut slot (`cut`);
//       the next byte is neither a header nor 0x80 (a fill byte: nothing can start
//       there)                                   -> the whole slot (16 bytes);
//       the next byte is 0x80 (another empty read, or a fill of 0x80): the whole slot
//       unless a packet-3 header starts inside it (bytes 2-15), then the byte alone.
//     So both forms decode, one count per read, for any fill whose bytes are not packet-3
//     headers (tested: 0x00, 0x80, 0xFF); a run of 16 or more lone 0x80 bytes counts as
//     whole slots. A fill that holds a header-like byte after 0x80 bytes can be read
//     as the start of a packet, as any data byte can: nothing in the format tells them
//     apart. Only 0x80 itself: a byte with bit 7 and other bits set (0xFF from a bus
//     that floats high) is foreign, so a dead bus shows as resyncs, not as an empty FIFO.
//   - a packet-3 header with fewer than 16 bytes left: a cut packet (power lost
//     mid-burst), `cut`, its bytes not decoded. A packet cut in the middle of a
//     recording cannot be told by its header: it is taken with the next bytes, and the
//     damage shows as a resync after it (the format holds no checksum);
//   - any other header: foreign. Nothing marks where the next packet starts. The driver
//     drops the rest of the burst and flushes the FIFO (the chip restarts on a packet
//     boundary); a recording has no flush, so its reader skips to the next boundary that
//     two packets confirm (resync_bytes()).
#pragma once

#include <cstddef>
#include <cstdint>

#include "aloft/cold_path.hpp"
#include "aloft/sensor/icm42688p_registers.hpp"
#include "aloft/sensor/imu_sample.hpp"

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

inline std::uint16_t stamp_of(const std::uint8_t* packet) {
  return static_cast<std::uint16_t>(big_endian_i16(packet + kPacket3TimestampOffset));
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
  p.timestamp = stamp_of(bytes);
  return p;
}

// Some axis at -32768, -32767 or +32767: the packet may be invalid or clipped, and the
// two tests below decide. One comparison per axis, no branch, for the packets that hold
// none (nearly all): about 20 instructions per sample fewer on a Cortex-M4F.
inline bool holds_extreme_value(const RawPacket3& p) {
  bool extreme = false;
  for (int axis = 0; axis < 3; ++axis) {
    // v + 32766 falls outside [0, 65532] exactly for those three values.
    extreme |= static_cast<unsigned>(p.accel[axis] + 32766) > 65532u;
    extreme |= static_cast<unsigned>(p.gyro[axis] + 32766) > 65532u;
  }
  return extreme;
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
  sample,      // `out` holds a new sample
  invalid,     // a -32768 packet: dropped, the clock moved on
  empty_read,  // 0x80, HEADER_MSG: the FIFO was empty (next() only)
  // The walk cannot go on from here (the two last, so that one comparison finds them):
  foreign_header,  // not packet 3: nothing decoded, no state changed
  cut,             // the bytes end inside a packet or an empty slot (next() only)
};

// One item of a walk over FIFO bytes: what it was, and how many bytes it took (0 for a
// foreign header: where the next item starts is the caller's to find).
struct FifoStep {
  PacketOutcome outcome;
  std::uint16_t bytes;
};

inline bool is_empty_read_header(std::uint8_t header) { return header == kHeaderMsg; }

// Bytes taken by the empty read whose 0x80 byte is bytes[0] (`left` ≥ 1 bytes from
// there), by the rule at the top of this file; 0 when the bytes end inside its slot.
ALOFT_COLD inline std::uint16_t empty_read_bytes(const std::uint8_t* bytes, std::size_t left) {
  if (left == 1 || is_packet3_header(bytes[1])) return 1;
  if (left < kPacket3Bytes) return is_empty_read_header(bytes[1]) ? 1 : 0;
  if (is_empty_read_header(bytes[1])) {
    for (std::uint16_t i = 2; i < kPacket3Bytes; ++i) {
      if (is_packet3_header(bytes[i])) return 1;
    }
  }
  return kPacket3Bytes;
}

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
    const bool extreme = holds_extreme_value(raw);
    const bool valid = !extreme || !holds_invalid_value(raw);
    // Before the first valid packet there is no time base yet, and nothing to lose.
    if (!started_) {
      if (!valid) return PacketOutcome::invalid;
      start_clock(raw.timestamp);
    } else {
      advance_clock(raw.timestamp);
    }
    if (!valid) return PacketOutcome::invalid;
    out = to_sample(raw, extreme);
    if (ticks_ - last_sample_ticks_ > gap_threshold_ticks_) add_flag(out, imu_gap_before);
    last_sample_ticks_ = ticks_;
    return PacketOutcome::sample;
  }

  // The next item of `left` ≥ 1 bytes of FIFO_DATA (the rules at the top of this file).
  FifoStep next(const std::uint8_t* bytes, std::size_t left, ImuSample<Scalar>& out) {
    const auto rest = static_cast<std::uint16_t>(left < kPacket3Bytes ? left : 0);  // a cut's bytes
    if (is_packet3_header(bytes[0])) {
      return rest > 0 ? FifoStep{PacketOutcome::cut, rest} : FifoStep{decode(bytes, out), kPacket3Bytes};
    }
    if (!is_empty_read_header(bytes[0])) return {PacketOutcome::foreign_header, 0};
    const std::uint16_t n = empty_read_bytes(bytes, left);
    return n > 0 ? FifoStep{PacketOutcome::empty_read, n} : FifoStep{PacketOutcome::cut, rest};
  }

  // After a foreign header at bytes[0]: the bytes to skip (≥ 1, at most `left`) to the
  // next packet boundary, confirmed by two packet-3 headers 16 bytes apart whose stamps
  // are 0.5 to 1.5 periods apart. A data byte can look like a header (a gyro at 28 rad/s
  // has a high byte of 0x68), but then the "stamps" are data too: the chance that a wrong
  // offset passes is about (4/256)² × 1/64, 4e-6. A last packet without a successor is
  // skipped with the rest. Host only: the driver flushes instead.
  std::size_t resync_bytes(const std::uint8_t* bytes, std::size_t left) const {
    const std::uint64_t period = gap_threshold_ticks_ * 2 / 3;
    for (std::size_t at = 1; at + 2 * kPacket3Bytes <= left; ++at) {
      const std::uint8_t* a = bytes + at;
      if (!is_packet3_header(a[0]) || !is_packet3_header(a[kPacket3Bytes])) continue;
      const auto step = static_cast<std::uint16_t>(stamp_of(a + kPacket3Bytes) - stamp_of(a));
      if (2 * step >= period && step <= gap_threshold_ticks_) return at;
    }
    return left;
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

  ImuSample<Scalar> to_sample(const RawPacket3& raw, bool extreme) const {
    ImuSample<Scalar> s;
    s.t_us = time_us();
    for (int axis = 0; axis < 3; ++axis) {
      s.accel_m_s2[axis] = static_cast<Scalar>(raw.accel[axis]) * accel_m_s2_per_lsb<Scalar>();
      s.gyro_rad_s[axis] = static_cast<Scalar>(raw.gyro[axis]) * gyro_rad_s_per_lsb<Scalar>();
    }
    if (extreme && at_full_scale(raw.accel)) add_flag(s, imu_accel_clipped);
    if (extreme && at_full_scale(raw.gyro)) add_flag(s, imu_gyro_clipped);
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
