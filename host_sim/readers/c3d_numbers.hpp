// Numbers as the three C3D processor formats store them (C3D User Guide, "processor
// type" 84/85/86 in the parameter section's fourth byte):
//   Intel (84): little-endian integers, IEEE-754 floats, little-endian;
//   DEC   (85): little-endian integers, VAX F_floating floats;
//   MIPS  (86): SGI/MIPS, big-endian integers and IEEE-754 floats.
// VAX F_floating stores two little-endian 16-bit words, the high word (sign, 8-bit
// exponent with bias 128, top fraction bits) first, and a hidden bit worth 0.5 rather
// than 1: its bits, words swapped, read as an IEEE float 4 times the value.
//
// ByteView is the bounded access every C3D read goes through: at() returns nullptr
// rather than a pointer past the end, so a damaged file cannot cause an out-of-bounds read.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace aloft::host::c3d {

enum class Processor : std::uint8_t { intel = 84, dec = 85, mips = 86 };

inline const char* processor_name(Processor p) {
  switch (p) {
    case Processor::intel: return "intel";
    case Processor::dec: return "dec";
    case Processor::mips: return "mips";
  }
  return "unknown";
}

class ByteView {
 public:
  explicit ByteView(const std::vector<std::uint8_t>& bytes) : data_(bytes.data()), size_(bytes.size()) {}
  std::size_t size() const { return size_; }
  // The `count` bytes at `offset`, or nullptr when any of them lies outside the file.
  const std::uint8_t* at(std::size_t offset, std::size_t count) const {
    if (offset > size_ || count > size_ - offset) return nullptr;
    return data_ + offset;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
};

inline std::uint16_t decode_u16(const std::uint8_t* p, Processor format) {
  if (format == Processor::mips) return static_cast<std::uint16_t>((p[0] << 8) | p[1]);
  return static_cast<std::uint16_t>((p[1] << 8) | p[0]);
}

inline std::int16_t decode_i16(const std::uint8_t* p, Processor format) {
  return static_cast<std::int16_t>(decode_u16(p, format));
}

inline float decode_f32(const std::uint8_t* p, Processor format) {
  std::uint32_t bits = 0;
  switch (format) {
    case Processor::intel:
      bits = std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
             std::uint32_t(p[3]) << 24;
      break;
    case Processor::mips:
      bits = std::uint32_t(p[3]) | std::uint32_t(p[2]) << 8 | std::uint32_t(p[1]) << 16 |
             std::uint32_t(p[0]) << 24;
      break;
    case Processor::dec: {
      // Words swapped: sign, exponent and fraction now sit where IEEE puts them.
      bits = std::uint32_t(p[2]) | std::uint32_t(p[3]) << 8 | std::uint32_t(p[0]) << 16 |
             std::uint32_t(p[1]) << 24;
      const int exponent = static_cast<int>((bits >> 23) & 0xFFu);
      // Exponent 0 is zero in VAX (with the sign set, a "reserved operand": read as 0).
      if (exponent == 0) return 0.0f;
      const double mantissa = static_cast<double>((bits & 0x7FFFFFu) | 0x800000u);  // 0.1fff..
      const double magnitude = std::ldexp(mantissa, exponent - 128 - 24);
      return static_cast<float>((bits & 0x80000000u) ? -magnitude : magnitude);
    }
  }
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace aloft::host::c3d
