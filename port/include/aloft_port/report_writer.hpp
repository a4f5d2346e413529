// Heap-free text formatting on top of port::write_text: integers and fixed-point numbers
// for test results and the example's report. Written by hand because newlib's printf of
// a float reaches for the heap (its dtoa allocates), which the cortex_m port forbids.
#pragma once

#include <cmath>
#include <cstdint>

#include "aloft_port/divide_u64.hpp"
#include "aloft_port/port.hpp"

namespace aloft {
namespace port {

class ReportWriter {
 public:
  using Sink = void (*)(const char* text);

  // Writes through sink: the port's text output unless told otherwise (tests capture).
  explicit ReportWriter(Sink sink = write_text) : sink_(sink) {}

  ReportWriter& text(const char* s) {
    sink_(s);
    return *this;
  }

  // Text output is for reports, never on a per-sample path: kept small and out of line.
  [[gnu::cold, gnu::noinline]] ReportWriter& integer(std::int64_t value) {
    char buffer[24];
    char* end = buffer + sizeof(buffer);
    char* p = end;
    *--p = '\0';
    const bool negative = value < 0;
    // Work with the magnitude in unsigned arithmetic, so INT64_MIN is printed right.
    std::uint64_t magnitude =
        negative ? std::uint64_t(0) - static_cast<std::uint64_t>(value) : static_cast<std::uint64_t>(value);
    do {
      std::uint32_t digit = 0;
      magnitude = divide_u64(magnitude, 10u, digit);
      *--p = static_cast<char>('0' + digit);
    } while (magnitude != 0u);
    if (negative) *--p = '-';
    sink_(p);
    return *this;
  }

  // value with `decimals` digits after the point (at most 9), rounded half away from zero.
  // Float and 32-bit integer arithmetic only: libgcc converts float to 64-bit integers
  // through double, which a single-precision FPU does in software. Digits beyond the
  // 1e9 place are written as zeros (a float has only 7 significant digits anyway).
  // NaN and infinities are written as "nan", "inf", "-inf".
  [[gnu::cold, gnu::noinline]] ReportWriter& fixed(float value, int decimals) {
    if (std::isnan(value)) return text("nan");
    if (std::isinf(value)) return text(value > 0.0f ? "inf" : "-inf");
    if (decimals < 0) decimals = 0;
    if (decimals > 9) decimals = 9;
    std::uint32_t scale = 1;
    for (int i = 0; i < decimals; ++i) scale *= 10u;
    const bool negative = value < 0.0f;
    float magnitude = negative ? -value : value;
    int trailing_zeros = 0;
    while (magnitude >= 1e9f) {
      magnitude /= 10.0f;
      ++trailing_zeros;
    }
    // Integer and fraction parts separately, so large values keep their integer digits.
    std::uint32_t whole = static_cast<std::uint32_t>(magnitude);
    std::uint32_t fraction =
        trailing_zeros > 0 ? 0u
                           : static_cast<std::uint32_t>(
                                 (magnitude - static_cast<float>(whole)) * static_cast<float>(scale) + 0.5f);
    if (fraction >= scale) {
      fraction -= scale;
      ++whole;
    }
    if (negative) text("-");
    integer(whole);
    for (; trailing_zeros > 0; --trailing_zeros) text("0");
    if (decimals > 0) {
      char digits[12];
      digits[0] = '.';
      for (int i = decimals; i >= 1; --i) {
        digits[i] = static_cast<char>('0' + fraction % 10u);
        fraction /= 10u;
      }
      digits[decimals + 1] = '\0';
      text(digits);
    }
    return *this;
  }

  // A byte as 0x and two upper-case hex digits ("0x47"): register values.
  ReportWriter& hex_byte(std::uint8_t value) {
    const char digits[] = "0123456789ABCDEF";
    const char hex[] = {'0', 'x', digits[value >> 4], digits[value & 0xFu], '\0'};
    return text(hex);
  }

  ReportWriter& line() { return text("\n"); }

 private:
  Sink sink_;
};

}  // namespace port
}  // namespace aloft
