// The Cortex-M4 core's own registers, the same on every board with this core (ARMv7-M
// Architecture Reference Manual; ST's PM0214, "STM32 Cortex-M4 MCUs and MPUs programming
// manual", §4): SysTick and the System Control Block register the startup code uses.
// Board registers live in the board's own header (../stm32f405/stm32f405_registers.hpp).
#pragma once

#include <cstdint>

namespace aloft {
namespace port {
namespace core {

// SysTick at 0xE000E010 (ARMv7-M ARM B3.3; PM0214 §4.5).
struct SysTickRegisters {
  volatile std::uint32_t control;  // SYST_CSR
  volatile std::uint32_t reload;   // SYST_RVR
  volatile std::uint32_t current;  // SYST_CVR, counts down
  volatile std::uint32_t calibration;
};
inline SysTickRegisters& systick() { return *reinterpret_cast<SysTickRegisters*>(0xE000E010u); }
constexpr std::uint32_t systick_enable = 1u << 0;
constexpr std::uint32_t systick_interrupt = 1u << 1;
constexpr std::uint32_t systick_processor_clock = 1u << 2;

// System Control Block (PM0214 §4.4): CPACR, whose CP10 and CP11 fields switch the FPU
// on (§4.6.1).
inline volatile std::uint32_t& scb_cpacr() { return *reinterpret_cast<volatile std::uint32_t*>(0xE000ED88u); }
constexpr std::uint32_t cpacr_fpu_full_access = 0xFu << 20;

// Floating-point context control register (PM0214 §4.6.2; ARMv7-M ARM B3.2.20), reset value
// 0xC0000000: ASPEN set, so the first FPU instruction sets CONTROL.FPCA and every exception
// from then on stacks the extended frame (PM0214 §2.3.7, Figure 12: 26 words, S0-S15 and
// FPSCR besides the 8 core registers), with LSPEN set deferring the FP part (lazy stacking)
// but reserving its room all the same. With ASPEN clear, FPCA stays 0 and every exception
// stacks the 8-word basic frame; the FP registers are then not preserved across an
// exception, which is sound only while no handler touches them (startup.cpp).
inline volatile std::uint32_t& fpu_fpccr() { return *reinterpret_cast<volatile std::uint32_t*>(0xE000EF34u); }
constexpr std::uint32_t fpccr_aspen = 1u << 31;
constexpr std::uint32_t fpccr_lspen = 1u << 30;

}  // namespace core
}  // namespace port
}  // namespace aloft
