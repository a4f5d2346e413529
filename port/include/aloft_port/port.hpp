// The platform contract: all that aloft's firmware-side programs (the bare-metal test
// runner, the example firmware) need from a board. A port is one .cpp file defining these
// functions; port/template/port_template.cpp is the stub to copy for a new board.
//
// Rules every port keeps: no heap, no exceptions; each function may be called from main
// only (not from interrupt handlers); init() is called once before the others.
#pragma once

#include <cstdint>

namespace aloft {
namespace port {

// Brings up what the others need: clocks, the tick counter, the output channel.
void init();

// Monotonic time source: ticks since init(), at ticks_per_second(). The count never
// wraps in practice (64 bits).
std::uint64_t ticks();
std::uint32_t ticks_per_second();

// Text output for reports and test results: writes the NUL-terminated string as is (no
// newline is added). Blocking; may be slow (a semihosting call on cortex_m).
void write_text(const char* text);

// Ends the program. status 0 means success; anything else is a failure that the runner
// (ctest, QEMU, a debugger) must see. On a board with nothing to return to, the port
// reports the status as best it can and halts.
[[noreturn]] void exit_with_status(int status);

}  // namespace port
}  // namespace aloft
