// Byte-by-byte little-endian encoding of the integers and IEEE-754 binary32 numbers that
// aloft stores (flight records, hashes). Written out byte by byte, never by copying a
// struct, so that the host and every target read and write the same bytes whatever their
// own byte order, padding or alignment rules.
#pragma once

#include <cstdint>
#include <cstring>

namespace aloft {
namespace le {

inline void put_u8(std::uint8_t* p, std::uint8_t v) { p[0] = v; }

inline void put_u16(std::uint8_t* p, std::uint16_t v) {
  p[0] = static_cast<std::uint8_t>(v);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}

inline void put_u32(std::uint8_t* p, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}

inline void put_u64(std::uint8_t* p, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}

// The number's IEEE-754 bit pattern (a float is binary32 on every aloft target).
inline void put_f32(std::uint8_t* p, float v) {
  static_assert(sizeof(float) == 4, "binary32 float");
  std::uint32_t bits = 0;
  std::memcpy(&bits, &v, 4);
  put_u32(p, bits);
}

inline std::uint16_t get_u16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | (p[1] << 8)); }

inline std::uint32_t get_u32(const std::uint8_t* p) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

inline std::uint64_t get_u64(const std::uint8_t* p) {
  std::uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

inline float get_f32(const std::uint8_t* p) {
  const std::uint32_t bits = get_u32(p);
  float v = 0.0f;
  std::memcpy(&v, &bits, 4);
  return v;
}

}  // namespace le
}  // namespace aloft
