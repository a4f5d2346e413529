// 64-bit unsigned division by a divisor below 2^16, in three 32-bit divisions. Exact; it
// keeps libgcc's general 64-bit division (__udivmoddi4, 700 bytes) out of a Cortex-M
// image whose 64-bit divisions are all by small numbers (10 for digits, 1000 for time
// units, the clock's ticks per µs).
#pragma once

#include <cstdint>

namespace aloft {
namespace port {

// n / d, with n % d in `remainder`; d must be in [1, 65535].
inline std::uint64_t divide_u64(std::uint64_t n, std::uint32_t d, std::uint32_t& remainder) {
  // Long division in digits of 16 bits below the top 32: each partial dividend is below
  // d * 2^16 < 2^32, so each step fits 32-bit arithmetic.
  const auto high = static_cast<std::uint32_t>(n >> 32);
  const std::uint32_t q_high = high / d;
  const std::uint32_t mid = ((high % d) << 16) | static_cast<std::uint32_t>((n >> 16) & 0xFFFFu);
  const std::uint32_t q_mid = mid / d;
  const std::uint32_t low = ((mid % d) << 16) | static_cast<std::uint32_t>(n & 0xFFFFu);
  remainder = low % d;
  return (static_cast<std::uint64_t>(q_high) << 32) | (static_cast<std::uint64_t>(q_mid) << 16) | (low / d);
}

}  // namespace port
}  // namespace aloft
