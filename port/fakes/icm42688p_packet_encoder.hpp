// ICM-42688-P FIFO packets made from samples, written from the datasheet (DS-000347 §6,
// "FIFO packet structure") and deliberately NOT from lib/'s decoder: the tests check the
// decoder against these bytes, so the two must not share a mistake. No heap: it runs in
// the fake chip on the bare-metal targets too.
//
// Packet 3, 16 bytes:
//   byte 0        header 0b0110'1000: HEADER_ACCEL (bit 6), HEADER_GYRO (bit 5),
//                 HEADER_TIMESTAMP_FSYNC = 10 (bits 3:2, "packet holds an ODR time stamp")
//   bytes 1-6     ACCEL_DATA_X1, X0, Y1, Y0, Z1, Z0
//   bytes 7-12    GYRO_DATA_X1, X0, Y1, Y0, Z1, Z0
//   byte 13       TEMP_DATA (8-bit in packets 1-3)
//   bytes 14-15   TIME_STAMP[15:8], [7:0]
// Multi-byte fields are big-endian when INTF_CONFIG0 SENSOR_DATA_ENDIAN = 1 (its reset
// value), little-endian otherwise. -32768 marks an axis without valid data.
#pragma once

#include <cstdint>

namespace aloft_test {

// What the sensor measured, in raw counts (±16 g: 2048 LSB/g; ±2000 °/s: 16.4 LSB/(°/s)).
struct ChipSample {
  std::int16_t accel[3] = {0, 0, 0};
  std::int16_t gyro[3] = {0, 0, 0};
  std::int8_t temperature = 0;
};

constexpr std::uint8_t kEncoderPacket3Header = 0x68;
constexpr int kEncoderPacket3Bytes = 16;
constexpr std::int16_t kEncoderNoData = -32768;

inline void put_16(std::uint8_t* at, std::uint16_t value, bool big_endian) {
  const auto high = static_cast<std::uint8_t>(value >> 8);
  const auto low = static_cast<std::uint8_t>(value & 0xFF);
  at[0] = big_endian ? high : low;
  at[1] = big_endian ? low : high;
}

inline void encode_packet3(const ChipSample& s, std::uint16_t stamp, bool big_endian,
                           std::uint8_t (&out)[kEncoderPacket3Bytes]) {
  out[0] = kEncoderPacket3Header;
  for (int axis = 0; axis < 3; ++axis) {
    put_16(out + 1 + 2 * axis, static_cast<std::uint16_t>(s.accel[axis]), big_endian);
    put_16(out + 7 + 2 * axis, static_cast<std::uint16_t>(s.gyro[axis]), big_endian);
  }
  out[13] = static_cast<std::uint8_t>(s.temperature);
  put_16(out + 14, stamp, big_endian);
}

inline ChipSample no_data_sample() {
  ChipSample s;
  for (int axis = 0; axis < 3; ++axis) {
    s.accel[axis] = kEncoderNoData;
    s.gyro[axis] = kEncoderNoData;
  }
  return s;
}

// A deterministic, well-mixed sample stream (no heap, no <random>): every raw value from
// -32767 to 32767 occurs, including both full-scale ends; -32768 is mapped to -32767.
inline std::uint32_t mix32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

inline std::int16_t raw_value(std::uint32_t k, std::uint32_t channel) {
  const auto v = static_cast<std::int16_t>(static_cast<std::uint16_t>(mix32(k * 7u + channel) & 0xFFFFu));
  return v == kEncoderNoData ? static_cast<std::int16_t>(-32767) : v;
}

inline ChipSample mixed_sample(std::uint32_t k) {
  ChipSample s;
  for (std::uint32_t axis = 0; axis < 3; ++axis) {
    s.accel[axis] = raw_value(k, axis);
    s.gyro[axis] = raw_value(k, axis + 3);
  }
  s.temperature = static_cast<std::int8_t>(static_cast<std::uint8_t>(mix32(k * 7u + 6u) & 0x7Fu));
  return s;
}

}  // namespace aloft_test
