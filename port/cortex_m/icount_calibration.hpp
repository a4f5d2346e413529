// Instructions per port tick, measured rather than assumed, for the footprint timings
// (example/main.cpp, ../stm32f405/firmware/timing_main.cpp): a loop of known length, two
// instructions per turn. Under QEMU with -icount shift=0 every instruction is 1 ns of
// virtual time, so the count is exact; footprint_functions.cmake reads the two lines.
#pragma once

#include <cstdint>

#include "aloft_port/port.hpp"
#include "aloft_port/report_writer.hpp"

namespace aloft {
namespace port {

constexpr std::uint32_t calibration_turns = 100000;

inline std::uint64_t calibration_ticks() {
  std::uint32_t turns = calibration_turns;
  const std::uint64_t start = ticks();
  asm volatile("1: subs %0, %0, #1\n\tbne 1b" : "+r"(turns) : : "cc");
  return ticks() - start;
}

// Prints "calibration_instructions N" and "calibration_ticks T".
inline void report_calibration(ReportWriter& out) {
  out.text("calibration_instructions ").integer(2 * calibration_turns).line();
  out.text("calibration_ticks ").integer(static_cast<std::int64_t>(calibration_ticks())).line();
}

}  // namespace port
}  // namespace aloft
