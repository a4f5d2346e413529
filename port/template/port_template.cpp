// Template port: copy this file for a new board and fill in each function (TinyUSB's
// src/portable/template/ is the model). It compiles as it is, and every stub says what
// the real function must do; port/CMakeLists.txt builds it so that it keeps compiling.
#include "aloft_port/port.hpp"

namespace aloft {
namespace port {

void init() {
  // Start a free-running counter (e.g. SysTick or a 32-bit timer with an overflow
  // interrupt, or the DWT cycle counter) and the text output (a UART, RTT, semihosting).
}

std::uint64_t ticks() {
  // Return the counter extended to 64 bits, counting up from init().
  return 0;
}

std::uint32_t ticks_per_second() {
  // Return the counter's rate in Hz.
  return 1;
}

void write_text(const char* text) {
  // Send the characters up to the NUL, blocking until they are queued.
  (void)text;
}

void exit_with_status(int status) {
  // Report status to whatever runs the program (semihosting exit, a debugger breakpoint,
  // a status LED), then halt. Must not return.
  (void)status;
  for (;;) {
  }
}

}  // namespace port
}  // namespace aloft
