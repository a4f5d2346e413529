// Little-endian encoding of the integers and IEEE-754 binary32 numbers that aloft stores
// (flight records, hashes). Written number by number, never by copying a struct, so that
// the host and every target read and write the same bytes whatever their own byte order,
// padding or alignment rules.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace aloft {
namespace le {

// On a little-endian machine (x86-64 and every ARM target aloft builds for) a number's own
// bytes are its little-endian bytes: one copy of the whole number writes them, a single
// store on a Cortex-M4F where byte by byte cost 8-40 bytes of code a field (the record
// code, stm32f405 footprint.json). Elsewhere they are written byte by byte.
#if defined(__BYTE_ORDER__) && defined(__ORDER_LITTLE_ENDIAN__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
constexpr bool native_is_little_endian = true;
#else
constexpr bool native_is_little_endian = false;
#endif

template <typename Unsigned>
inline void put(std::uint8_t* p, Unsigned v) {
  if (native_is_little_endian) {
    std::memcpy(p, &v, sizeof v);
    return;
  }
  for (std::size_t i = 0; i < sizeof v; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}

template <typename Unsigned>
inline Unsigned get(const std::uint8_t* p) {
  Unsigned v = 0;
  if (native_is_little_endian) {
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  for (std::size_t i = sizeof v; i-- > 0;) v = static_cast<Unsigned>((v << 8) | p[i]);
  return v;
}

inline void put_u8(std::uint8_t* p, std::uint8_t v) { p[0] = v; }
inline void put_u16(std::uint8_t* p, std::uint16_t v) { put(p, v); }
inline void put_u32(std::uint8_t* p, std::uint32_t v) { put(p, v); }
inline void put_u64(std::uint8_t* p, std::uint64_t v) { put(p, v); }

// The number's IEEE-754 bit pattern (a float is binary32 on every aloft target).
inline void put_f32(std::uint8_t* p, float v) {
  static_assert(sizeof(float) == 4, "binary32 float");
  std::uint32_t bits = 0;
  std::memcpy(&bits, &v, 4);
  put_u32(p, bits);
}

// The float's upper 16 bits, rounded to nearest (bfloat16: its sign, exponent and 7
// mantissa bits, 0.4 % apart): for the figures a record keeps to a few digits.
inline void put_bf16(std::uint8_t* p, float v) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &v, 4);
  put_u16(p, static_cast<std::uint16_t>((bits + 0x8000u) >> 16));
}

inline std::uint16_t get_u16(const std::uint8_t* p) { return get<std::uint16_t>(p); }
inline std::uint32_t get_u32(const std::uint8_t* p) { return get<std::uint32_t>(p); }
inline std::uint64_t get_u64(const std::uint8_t* p) { return get<std::uint64_t>(p); }

inline float get_f32(const std::uint8_t* p) {
  const std::uint32_t bits = get_u32(p);
  float v = 0.0f;
  std::memcpy(&v, &bits, 4);
  return v;
}

inline float get_bf16(const std::uint8_t* p) {
  const std::uint32_t bits = static_cast<std::uint32_t>(get_u16(p)) << 16;
  float v = 0.0f;
  std::memcpy(&v, &bits, 4);
  return v;
}

}  // namespace le
}  // namespace aloft
