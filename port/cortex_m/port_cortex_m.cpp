// The platform contract (aloft_port/port.hpp) on a Cortex-M: SysTick as the time source
// (processor clock, extended to 64 bits by its wrap interrupt), text and exit status
// through semihosting (see semihosting.hpp). Board specifics (clocks): board.hpp.
#include "aloft_port/port.hpp"

#include "board.hpp"
#include "core_registers.hpp"
#include "semihosting.hpp"

namespace aloft {
namespace port {

namespace {

using core::systick;
constexpr std::uint32_t systick_reload = 0x00FFFFFFu;  // the full 24 bits: fewest interrupts

volatile std::uint32_t systick_wraps = 0;

}  // namespace

void init() {
  board::init_clocks();
  systick().control = 0;
  systick().reload = systick_reload;
  systick().current = 0;  // any write clears the counter
  systick_wraps = 0;
  systick().control = core::systick_enable | core::systick_interrupt | core::systick_processor_clock;
}

std::uint64_t ticks() {
  // Re-read when the wrap interrupt ran between the two reads of the count.
  std::uint32_t wraps;
  std::uint32_t current;
  do {
    wraps = systick_wraps;
    current = systick().current;
  } while (wraps != systick_wraps);
  // One period reads reload, reload - 1, ..., 1, 0, and the wrap interrupt comes as the
  // count reaches 0; so 0 is the first tick after a wrap (and the value right after init).
  const std::uint32_t into_period = current == 0 ? 0 : systick_reload + 1u - current;
  return static_cast<std::uint64_t>(wraps) * (systick_reload + 1u) + into_period;
}

std::uint32_t ticks_per_second() { return board::processor_clock_hz(); }

void write_text(const char* text) { semihosting::call(semihosting::Operation::write0, text); }

void exit_with_status(int status) {
  const std::uint32_t block[2] = {semihosting::application_exit, static_cast<std::uint32_t>(status)};
  semihosting::call(semihosting::Operation::exit_extended, block);
  // Only reached when no semihosting host took the exit.
  for (;;) {
    asm volatile("bkpt 0");
  }
}

}  // namespace port
}  // namespace aloft

extern "C" void SysTick_Handler() { aloft::port::systick_wraps = aloft::port::systick_wraps + 1u; }
