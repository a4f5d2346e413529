// The platform contract (aloft_port/port.hpp) on a Cortex-M: SysTick as the time source
// (processor clock, extended to 64 bits by its wrap interrupt), text and exit status
// through semihosting (see semihosting.hpp). Board specifics: board.hpp.
#include "aloft_port/port.hpp"

#include "board.hpp"
#include "semihosting.hpp"

namespace aloft {
namespace port {

namespace {

// SysTick, part of every ARMv7-M core (ARMv7-M Architecture Reference Manual, B3.3).
struct SysTickRegisters {
  volatile std::uint32_t control;  // SYST_CSR
  volatile std::uint32_t reload;   // SYST_RVR
  volatile std::uint32_t current;  // SYST_CVR, counts down
  volatile std::uint32_t calibration;
};
SysTickRegisters& systick() { return *reinterpret_cast<SysTickRegisters*>(0xE000E010u); }

constexpr std::uint32_t systick_reload = 0x00FFFFFFu;  // the full 24 bits: fewest interrupts
constexpr std::uint32_t systick_enable = 1u << 0;
constexpr std::uint32_t systick_interrupt = 1u << 1;
constexpr std::uint32_t systick_processor_clock = 1u << 2;

volatile std::uint32_t systick_wraps = 0;

}  // namespace

void init() {
  systick().control = 0;
  systick().reload = systick_reload;
  systick().current = 0;  // any write clears the counter
  systick_wraps = 0;
  systick().control = systick_enable | systick_interrupt | systick_processor_clock;
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

std::uint32_t ticks_per_second() { return board::processor_clock_hz; }

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
