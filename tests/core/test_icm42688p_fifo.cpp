// The ICM-42688-P FIFO decoder on packets encoded from the datasheet's layout
// (icm42688p_packet_encoder.hpp): units, full-scale flags, invalid data, headers, and the
// unwrapping of the 16-bit time stamps.
#include "aloft/sensor/icm42688p_fifo.hpp"
#include "icm42688p_packet_encoder.hpp"
#include "icm42688p_stream_check.hpp"
#include "test_api.hpp"

namespace {

using aloft::icm42688p::FifoDecoder;
using aloft::icm42688p::PacketOutcome;
using aloft::icm42688p::TimestampClock;
using aloft_test::ChipSample;

ChipSample sample_of(std::int16_t ax, std::int16_t ay, std::int16_t az, std::int16_t gx, std::int16_t gy,
                     std::int16_t gz) {
  ChipSample s;
  s.accel[0] = ax;
  s.accel[1] = ay;
  s.accel[2] = az;
  s.gyro[0] = gx;
  s.gyro[1] = gy;
  s.gyro[2] = gz;
  return s;
}

template <typename S>
PacketOutcome decode(FifoDecoder<S>& d, const ChipSample& s, std::uint16_t stamp, aloft::ImuSample<S>& out) {
  std::uint8_t bytes[aloft_test::kEncoderPacket3Bytes];
  aloft_test::encode_packet3(s, stamp, true, bytes);
  return d.decode(bytes, out);
}

template <typename S>
bool near(S a, double b, double relative) {
  const double d = static_cast<double>(a) - b;
  return (d < 0 ? -d : d) <= relative * (b < 0 ? -b : b);
}

template <typename S>
void check_units() {
  FifoDecoder<S> d(1000, TimestampClock::pll_or_external);
  aloft::ImuSample<S> out;
  // 1 g and -1 g; 10 °/s is 164 counts at 16.4 LSB/(°/s).
  ALOFT_REQUIRE(decode(d, sample_of(2048, 0, -2048, 164, -1640, 0), 100, out) == PacketOutcome::sample);
  ALOFT_CHECK(near(out.accel_m_s2[0], 9.80665, 1e-6));
  ALOFT_CHECK(near(out.accel_m_s2[2], -9.80665, 1e-6));
  ALOFT_CHECK(aloft_test::identical(out.accel_m_s2[1], S(0)));
  ALOFT_CHECK(near(out.gyro_rad_s[0], 10.0 * 3.14159265358979 / 180.0, 1e-6));
  ALOFT_CHECK(near(out.gyro_rad_s[1], -100.0 * 3.14159265358979 / 180.0, 1e-6));
  // One multiplication by a constant rounded once: the same count gives the same bits.
  ALOFT_CHECK(aloft_test::identical(out.accel_m_s2[0], S(2048) * aloft::icm42688p::accel_m_s2_per_lsb<S>()));
  ALOFT_CHECK(out.t_us == 0u);
  ALOFT_CHECK(out.flags == 0);
}

template <typename S>
void check_full_scale_and_invalid() {
  FifoDecoder<S> d(1000, TimestampClock::pll_or_external);
  aloft::ImuSample<S> out;
  ALOFT_REQUIRE(decode(d, sample_of(1, 32767, 3, 4, 5, 6), 0, out) == PacketOutcome::sample);
  ALOFT_CHECK(out.flags == aloft::imu_accel_clipped);
  ALOFT_REQUIRE(decode(d, sample_of(1, 2, 3, 4, -32767, 6), 1000, out) == PacketOutcome::sample);
  ALOFT_CHECK(out.flags == aloft::imu_gyro_clipped);
  // -32768 on one axis: no data; the clock moves on, and the next sample follows a gap.
  ALOFT_CHECK(decode(d, sample_of(1, 2, 3, 4, 5, -32768), 2000, out) == PacketOutcome::invalid);
  ALOFT_REQUIRE(decode(d, sample_of(1, 2, 3, 4, 5, 6), 3000, out) == PacketOutcome::sample);
  ALOFT_CHECK(out.t_us == 3000u);
  ALOFT_CHECK(out.gap_before());
  ALOFT_REQUIRE(decode(d, sample_of(1, 2, 3, 4, 5, 6), 4000, out) == PacketOutcome::sample);
  ALOFT_CHECK(!out.gap_before());
}

template <typename S>
void check_headers() {
  FifoDecoder<S> d(1000, TimestampClock::pll_or_external);
  aloft::ImuSample<S> out;
  std::uint8_t bytes[aloft_test::kEncoderPacket3Bytes];
  aloft_test::encode_packet3(sample_of(1, 2, 3, 4, 5, 6), 0, true, bytes);
  // HEADER_MSG (empty FIFO), an FSYNC stamp (bits 3:2 = 11), packet 4 (HEADER_20),
  // accel only: not packet 3.
  for (std::uint8_t header :
       {std::uint8_t{0x80}, std::uint8_t{0x6C}, std::uint8_t{0x78}, std::uint8_t{0x48}}) {
    bytes[0] = header;
    ALOFT_CHECK(d.decode(bytes, out) == PacketOutcome::foreign_header);
  }
  ALOFT_CHECK(!d.started());
  // The ODR-change bits (1:0) do not change the packet's layout.
  bytes[0] = 0x6B;
  ALOFT_CHECK(d.decode(bytes, out) == PacketOutcome::sample);
}

template <typename S>
void check_unwrapping() {
  FifoDecoder<S> d(1000, TimestampClock::pll_or_external);
  aloft::ImuSample<S> out;
  const ChipSample s = sample_of(1, 2, 3, 4, 5, 6);
  // Across three wraps of the 16-bit stamp, 1 ms apart.
  for (std::uint32_t k = 0; k < 200; ++k) {
    const auto stamp = static_cast<std::uint16_t>((0xFF00u + 1000u * k) & 0xFFFFu);
    ALOFT_REQUIRE(decode(d, s, stamp, out) == PacketOutcome::sample);
    ALOFT_CHECK(out.t_us == 1000u * k);
    ALOFT_CHECK(!out.gap_before());
  }
  // A 20 ms hole, shorter than a wrap: the stamps alone measure it.
  ALOFT_REQUIRE(decode(d, s, static_cast<std::uint16_t>((0xFF00u + 1000u * 219u) & 0xFFFFu), out) ==
                PacketOutcome::sample);
  ALOFT_CHECK(out.t_us == 219000u);
  ALOFT_CHECK(out.gap_before());
  // A 300 ms hole after a flush: the caller's estimate (off by 7 ms) picks the wrap
  // count, the stamps give the exact length.
  d.expect_gap(307000);
  ALOFT_REQUIRE(decode(d, s, static_cast<std::uint16_t>((0xFF00u + 1000u * 519u) & 0xFFFFu), out) ==
                PacketOutcome::sample);
  ALOFT_CHECK(out.t_us == 519000u);
  ALOFT_CHECK(out.gap_before());
  // The same without an estimate is measured modulo one wrap (65,536 µs).
  d.expect_gap(0);
  ALOFT_REQUIRE(decode(d, s, static_cast<std::uint16_t>((0xFF00u + 1000u * 819u) & 0xFFFFu), out) ==
                PacketOutcome::sample);
  ALOFT_CHECK(out.t_us == 519000u + 300000u % 65536u);
}

template <typename S>
void check_rc_clock() {
  FifoDecoder<S> d(1000, TimestampClock::internal_rc);
  aloft::ImuSample<S> out;
  const ChipSample s = sample_of(1, 2, 3, 4, 5, 6);
  ALOFT_REQUIRE(decode(d, s, 0, out) == PacketOutcome::sample);
  // 30 ticks of the RC-clocked counter are 32 µs (§12.7); 937.5 ticks per ms.
  ALOFT_REQUIRE(decode(d, s, 30, out) == PacketOutcome::sample);
  ALOFT_CHECK(out.t_us == 32u);
  ALOFT_REQUIRE(decode(d, s, 30 + 9375, out) == PacketOutcome::sample);
  ALOFT_CHECK(out.t_us == 10032u);
}

// The walk over FIFO bytes (next()): what each item is and how many bytes it takes.
template <typename S>
void check_walk() {
  using aloft::icm42688p::FifoStep;
  FifoDecoder<S> d(1000, TimestampClock::pll_or_external);
  aloft::ImuSample<S> out;
  std::uint8_t b[48] = {};
  const auto step = [&](std::size_t left) { return d.next(b, left, out); };
  const auto is = [](FifoStep st, PacketOutcome o, std::uint16_t n) {
    return st.outcome == o && st.bytes == n;
  };
  std::uint8_t packet[aloft_test::kEncoderPacket3Bytes];
  aloft_test::encode_packet3(sample_of(1, 2, 3, 4, 5, 6), 1000, true, packet);
  const auto put_packet = [&](int at) {
    for (int i = 0; i < 16; ++i) b[at + i] = packet[i];
  };
  const auto fill = [&](int from, int to, std::uint8_t v) {
    for (int i = from; i < to; ++i) b[i] = v;
  };
  // 0x80 then a packet header: the byte alone.
  b[0] = 0x80;
  put_packet(1);
  ALOFT_CHECK(is(step(17), PacketOutcome::empty_read, 1));
  ALOFT_CHECK(is(step(1), PacketOutcome::empty_read, 1));  // the last byte of the bytes
  // 0x80 and 15 fill bytes (0x00, 0xFF, 0x80): the whole slot.
  for (std::uint8_t f : {std::uint8_t{0x00}, std::uint8_t{0xFF}, std::uint8_t{0x80}}) {
    fill(1, 16, f);
    put_packet(16);
    ALOFT_CHECK(is(step(32), PacketOutcome::empty_read, 16));
  }
  // 0x80 0x80 and a packet: two lone bytes, the first one by the header inside the slot.
  b[1] = 0x80;
  put_packet(2);
  ALOFT_CHECK(is(step(18), PacketOutcome::empty_read, 1));
  // Fewer than 16 bytes left: 0x80 0x80 is a lone byte; 0x80 and fill is a cut slot.
  fill(0, 16, 0x80);
  ALOFT_CHECK(is(step(2), PacketOutcome::empty_read, 1));
  b[1] = 0x00;
  ALOFT_CHECK(is(step(5), PacketOutcome::cut, 5));
  // A packet cut by the end of the bytes; 0xFF and 0x3C are foreign (nothing taken).
  put_packet(0);
  ALOFT_CHECK(is(step(9), PacketOutcome::cut, 9));
  ALOFT_CHECK(!d.started());
  ALOFT_CHECK(is(step(16), PacketOutcome::sample, 16));
  b[0] = 0xFF;
  ALOFT_CHECK(is(step(16), PacketOutcome::foreign_header, 0));
  b[0] = 0x3C;
  ALOFT_CHECK(is(step(16), PacketOutcome::foreign_header, 0));
  // Resync: 3 junk bytes, then two packets one period apart: skip 3. A header-like byte
  // in the junk does not fool it (its "successor" is not a packet one period on).
  fill(0, 48, 0x00);
  b[0] = 0x3C;
  b[1] = 0x68;
  put_packet(3);
  aloft_test::encode_packet3(sample_of(1, 2, 3, 4, 5, 6), 2000, true, packet);
  put_packet(19);
  ALOFT_CHECK(d.resync_bytes(b, 35) == 3u);
  ALOFT_CHECK(d.resync_bytes(b, 34) == 34u);  // no confirmed pair: all skipped
  aloft_test::encode_packet3(sample_of(1, 2, 3, 4, 5, 6), 9000, true, packet);  // 8 periods on
  put_packet(19);
  ALOFT_CHECK(d.resync_bytes(b, 35) == 35u);
}

}  // namespace

ALOFT_TEST_CASE("ICM-42688-P packet 3 decodes to m/s² and rad/s", "[icm42688p]") {
  check_units<float>();
  check_units<double>();
}

ALOFT_TEST_CASE("ICM-42688-P full-scale counts are flagged, -32768 is dropped", "[icm42688p]") {
  check_full_scale_and_invalid<float>();
  check_full_scale_and_invalid<double>();
}

ALOFT_TEST_CASE("ICM-42688-P headers other than packet 3 are refused", "[icm42688p]") {
  check_headers<float>();
  check_headers<double>();
}

ALOFT_TEST_CASE("ICM-42688-P time stamps unwrap to 64-bit microseconds", "[icm42688p]") {
  check_unwrapping<float>();
  check_unwrapping<double>();
}

ALOFT_TEST_CASE("ICM-42688-P stamps on the internal RC clock are scaled by 32/30", "[icm42688p]") {
  check_rc_clock<float>();
  check_rc_clock<double>();
}

ALOFT_TEST_CASE("ICM-42688-P FIFO bytes: 0x80 empty reads, cut packets, foreign headers, resync",
                "[icm42688p]") {
  check_walk<float>();
  check_walk<double>();
}
