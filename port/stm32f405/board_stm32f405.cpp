// Clock bring-up for an STM32F405 flight controller (the board side of ../cortex_m/
// board.hpp): an 8 MHz crystal (HSE, what most F405 flight controllers carry) through
// the PLL to 168 MHz, the part's maximum (RM0090 §6.3.2, §7.2). Every wait on the
// hardware is bounded, and the outcome is one line of text: a board without a crystal
// falls back to the 16 MHz internal oscillator (HSI, running from reset).
// QEMU's netduinoplus2 does not model the RCC (its registers read 0) but clocks the core
// and SysTick at a fixed 168 MHz. A real part always reads HSIRDY set at that point (the
// HSI is on from reset and only switched off by software), so "HSI not ready" can only
// mean such a model, and the time base takes its 168 MHz. Registers:
// stm32f405_registers.hpp.
#include "../cortex_m/board.hpp"
#include "aloft_port/port.hpp"
#include "aloft_port/report_writer.hpp"
#include "stm32f405_registers.hpp"

namespace aloft {
namespace port {
namespace board {

namespace {

namespace r = stm32f405;
using namespace stm32f405::rcc_bits;

constexpr std::uint32_t hsi_hz = 16000000u;
constexpr std::uint32_t hse_hz = 8000000u;
constexpr std::uint32_t pll_hz = 168000000u;
// HSE / 8 = 1 MHz at the PLL's input (it wants 1..2 MHz), x 336 = a 336 MHz VCO,
// / 2 = 168 MHz SYSCLK, / 7 = 48 MHz for USB (RM0090 §7.3.2).
constexpr std::uint32_t pll_m = hse_hz / 1000000u;
constexpr std::uint32_t pll_n = 336u;
constexpr std::uint32_t pll_p = 2u;
constexpr std::uint32_t pll_q = 7u;
static_assert(hse_hz / pll_m * pll_n / pll_p == pll_hz, "PLL settings do not give 168 MHz");
// 168 MHz at 2.7..3.6 V needs 5 flash wait states (RM0090 §3.5.1, Table 10).
constexpr std::uint32_t flash_wait_states_168mhz = 5u;
// Polls of a ready flag before giving up. An HSE crystal starts within a few ms (the
// datasheet's t_SU(HSE) is 2 ms typical); 100000 polls are over 20 ms even at 16 MHz.
constexpr std::uint32_t max_polls = 100000u;

std::uint32_t running_hz = hsi_hz;

// Polls until (register & mask) == want, at most max_polls times; the polls it took, or
// max_polls + 1 when it gave up.
std::uint32_t wait_for(const volatile std::uint32_t& reg, std::uint32_t mask, std::uint32_t want) {
  for (std::uint32_t polls = 1; polls <= max_polls; ++polls) {
    if ((reg & mask) == want) return polls;
  }
  return max_polls + 1u;
}

constexpr std::uint32_t emulator_hz = 168000000u;  // QEMU netduinoplus2's SYSCLK_FRQ

// After a failed wait: back on the HSI, or, where no HSI is seen, on the emulator's clock.
void fall_back(const char* what) {
  const bool hsi_seen = (r::rcc().cr & cr_hsirdy) != 0;
  running_hz = hsi_seen ? hsi_hz : emulator_hz;
  ReportWriter out;
  out.text("stm32f405 clocks: ").text(what).text(" after ").integer(max_polls).text(" polls; ");
  out.text(hsi_seen ? "running on HSI 16 MHz\n" : "no RCC (HSI not ready either): QEMU's fixed 168 MHz\n");
}

}  // namespace

[[gnu::cold]] void init_clocks() {
  running_hz = hsi_hz;
  r::RccRegisters& rcc = r::rcc();
  rcc.cr = rcc.cr | cr_hseon;
  if (wait_for(rcc.cr, cr_hserdy, cr_hserdy) > max_polls) {
    rcc.cr = rcc.cr & ~cr_hseon;
    fall_back("HSE not ready");
    return;
  }
  rcc.pllcfgr = pllcfgr_m(pll_m) | pllcfgr_n(pll_n) | pllcfgr_p(pll_p) | pllcfgr_q(pll_q) | pllcfgr_src_hse;
  rcc.cr = rcc.cr | cr_pllon;
  if (wait_for(rcc.cr, cr_pllrdy, cr_pllrdy) > max_polls) {
    rcc.cr = rcc.cr & ~(cr_pllon | cr_hseon);
    fall_back("PLL not locked");
    return;
  }
  // Wait states before the faster clock, bus dividers before the switch.
  r::FlashRegisters& flash = r::flash();
  flash.acr = r::flash_bits::acr_latency(flash_wait_states_168mhz) | r::flash_bits::acr_prften |
              r::flash_bits::acr_icen | r::flash_bits::acr_dcen;
  rcc.cfgr = cfgr_hpre_div1 | cfgr_ppre1_div4 | cfgr_ppre2_div2;
  rcc.cfgr = (rcc.cfgr & ~cfgr_sw_mask) | cfgr_sw_pll;
  if (wait_for(rcc.cfgr, cfgr_sws_mask, cfgr_sws_pll) > max_polls) {
    rcc.cfgr = rcc.cfgr & ~cfgr_sw_mask;
    fall_back("switch to PLL not taken");
    return;
  }
  running_hz = pll_hz;
  write_text("stm32f405 clocks: HSE ready, PLL locked; running at 168 MHz\n");
}

std::uint32_t processor_clock_hz() { return running_hz; }

}  // namespace board
}  // namespace port
}  // namespace aloft
