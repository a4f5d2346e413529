// The STM32F405's peripheral registers that aloft uses, written by hand from the
// reference manual, since no CMSIS device package is available: RM0090 Rev 19
// ("STM32F405/415, STM32F407/417, STM32F427/437 and STM32F429/439 advanced Arm-based
// 32-bit MCUs"). Each block gives its base address (§2.3, Table 1 "STM32F4xx register
// boundary addresses") and the section of its register map; offsets and bits are the
// manual's. The Cortex-M4 core's own registers (SysTick, SCB) are the same on every
// board: ../cortex_m/core_registers.hpp, included here.
//
// Under QEMU's netduinoplus2 (hw/arm/stm32f405_soc.c) SPI1..3, USART1/2/3/6, TIM2..5,
// SYSCFG, EXTI and ADC are modelled; RCC, FLASH interface and GPIO are not: their reads
// return 0 and their writes are dropped. Code that waits on them must bound the wait.
#pragma once

#include <cstdint>

#include "../cortex_m/core_registers.hpp"

namespace aloft {
namespace port {
namespace stm32f405 {

using Register = volatile std::uint32_t;

template <typename Block>
Block& at(std::uintptr_t address) {
  return *reinterpret_cast<Block*>(address);
}

// ---- RCC: reset and clock control, 0x40023800 (RM0090 §7.3.24 register map) ----
struct RccRegisters {
  Register cr;        // 0x00 §7.3.1
  Register pllcfgr;   // 0x04 §7.3.2
  Register cfgr;      // 0x08 §7.3.3
  Register cir;       // 0x0C §7.3.4
  Register ahb1rstr;  // 0x10 §7.3.5
  Register ahb2rstr;  // 0x14 §7.3.6
  Register ahb3rstr;  // 0x18 §7.3.7
  Register reserved0;
  Register apb1rstr;  // 0x20 §7.3.8
  Register apb2rstr;  // 0x24 §7.3.9
  Register reserved1[2];
  Register ahb1enr;  // 0x30 §7.3.10
  Register ahb2enr;  // 0x34 §7.3.11
  Register ahb3enr;  // 0x38 §7.3.12
  Register reserved2;
  Register apb1enr;  // 0x40 §7.3.13
  Register apb2enr;  // 0x44 §7.3.14
};
inline RccRegisters& rcc() { return at<RccRegisters>(0x40023800u); }
namespace rcc_bits {
constexpr std::uint32_t cr_hsion = 1u << 0;
constexpr std::uint32_t cr_hsirdy = 1u << 1;
constexpr std::uint32_t cr_hseon = 1u << 16;
constexpr std::uint32_t cr_hserdy = 1u << 17;
constexpr std::uint32_t cr_pllon = 1u << 24;
constexpr std::uint32_t cr_pllrdy = 1u << 25;
// PLLCFGR: VCO = source / M * N, SYSCLK = VCO / P, USB/SDIO = VCO / Q.
constexpr std::uint32_t pllcfgr_m(std::uint32_t m) { return m << 0; }             // 2..63
constexpr std::uint32_t pllcfgr_n(std::uint32_t n) { return n << 6; }             // 50..432
constexpr std::uint32_t pllcfgr_p(std::uint32_t p) { return (p / 2 - 1) << 16; }  // 2, 4, 6, 8
constexpr std::uint32_t pllcfgr_src_hse = 1u << 22;
constexpr std::uint32_t pllcfgr_q(std::uint32_t q) { return q << 24; }  // 2..15
constexpr std::uint32_t cfgr_sw_mask = 3u << 0;
constexpr std::uint32_t cfgr_sw_pll = 2u << 0;
constexpr std::uint32_t cfgr_sws_mask = 3u << 2;
constexpr std::uint32_t cfgr_sws_pll = 2u << 2;
constexpr std::uint32_t cfgr_hpre_div1 = 0u << 4;
constexpr std::uint32_t cfgr_ppre1_div4 = 5u << 10;  // APB1 at most 42 MHz
constexpr std::uint32_t cfgr_ppre2_div2 = 4u << 13;  // APB2 at most 84 MHz
constexpr std::uint32_t ahb1enr_gpioa = 1u << 0;
constexpr std::uint32_t apb1enr_tim2 = 1u << 0;
constexpr std::uint32_t apb1enr_usart2 = 1u << 17;
constexpr std::uint32_t apb2enr_usart1 = 1u << 4;
constexpr std::uint32_t apb2enr_spi1 = 1u << 12;
}  // namespace rcc_bits

// ---- FLASH interface, 0x40023C00 (RM0090 §3.9.7 register map) ----
struct FlashRegisters {
  Register acr;      // 0x00 §3.9.1 access control: wait states, caches
  Register keyr;     // 0x04 §3.9.2 unlocks CR
  Register optkeyr;  // 0x08 §3.9.3 unlocks OPTCR
  Register sr;       // 0x0C §3.9.4 status
  Register cr;       // 0x10 §3.9.5 control
  Register optcr;    // 0x14 §3.9.6 option control
};
inline FlashRegisters& flash() { return at<FlashRegisters>(0x40023C00u); }
namespace flash_bits {
constexpr std::uint32_t acr_latency(std::uint32_t wait_states) { return wait_states << 0; }
constexpr std::uint32_t acr_latency_mask = 7u << 0;
constexpr std::uint32_t acr_prften = 1u << 8;
constexpr std::uint32_t acr_icen = 1u << 9;
constexpr std::uint32_t acr_dcen = 1u << 10;
constexpr std::uint32_t acr_dcrst = 1u << 12;  // data cache reset, only while DCEN is 0 (§3.5.2)
constexpr std::uint32_t key1 = 0x45670123u;  // §3.5.1: KEYR takes key1 then key2
constexpr std::uint32_t key2 = 0xCDEF89ABu;
constexpr std::uint32_t optkey1 = 0x08192A3Bu;  // §3.6.2
constexpr std::uint32_t optkey2 = 0x4C5D6E7Fu;
constexpr std::uint32_t sr_eop = 1u << 0;
constexpr std::uint32_t sr_operr = 1u << 1;
constexpr std::uint32_t sr_wrperr = 1u << 4;
constexpr std::uint32_t sr_pgaerr = 1u << 5;
constexpr std::uint32_t sr_pgperr = 1u << 6;
constexpr std::uint32_t sr_pgserr = 1u << 7;
constexpr std::uint32_t sr_bsy = 1u << 16;
constexpr std::uint32_t cr_pg = 1u << 0;
constexpr std::uint32_t cr_ser = 1u << 1;
constexpr std::uint32_t cr_mer = 1u << 2;
constexpr std::uint32_t cr_snb(std::uint32_t sector) { return sector << 3; }  // 0..11
constexpr std::uint32_t cr_snb_mask = 0xFu << 3;
constexpr std::uint32_t cr_psize_x8 = 0u << 8;  // program 8 bits at a time (any supply voltage)
constexpr std::uint32_t cr_psize_x16 = 1u << 8;
constexpr std::uint32_t cr_psize_x32 = 2u << 8;  // 2.7 V to 3.6 V
constexpr std::uint32_t cr_psize_mask = 3u << 8;
constexpr std::uint32_t cr_strt = 1u << 16;
constexpr std::uint32_t cr_lock = 1u << 31;
constexpr std::uint32_t optcr_optlock = 1u << 0;
constexpr std::uint32_t optcr_optstrt = 1u << 1;
}  // namespace flash_bits

// ---- GPIO port A, 0x40020000 (RM0090 §8.4.11 register map) ----
struct GpioRegisters {
  Register moder;    // 0x00 §8.4.1 two bits per pin: 00 input, 01 output, 10 alternate
  Register otyper;   // 0x04 §8.4.2
  Register ospeedr;  // 0x08 §8.4.3 two bits per pin: 11 very high speed
  Register pupdr;    // 0x0C §8.4.4
  Register idr;      // 0x10 §8.4.5
  Register odr;      // 0x14 §8.4.6
  Register bsrr;     // 0x18 §8.4.7 bit n sets pin n, bit n + 16 resets it (atomic)
  Register lckr;     // 0x1C §8.4.8
  Register afr[2];   // 0x20, 0x24 §8.4.9-10 four bits per pin: alternate function number
};
constexpr std::uintptr_t gpioa_base = 0x40020000u;
inline GpioRegisters& gpioa() { return at<GpioRegisters>(gpioa_base); }
namespace gpio_bits {
constexpr std::uint32_t mode_output = 1u;
constexpr std::uint32_t mode_alternate = 2u;
constexpr std::uint32_t speed_very_high = 3u;
constexpr std::uint32_t af_spi1 = 5u;  // AF5: SPI1/SPI2 (datasheet DS8626, Table 9)
}  // namespace gpio_bits

// ---- SPI1, 0x40013000 (RM0090 §28.5.10 register map) ----
struct SpiRegisters {
  Register cr1;      // 0x00 §28.5.1
  Register cr2;      // 0x04 §28.5.2
  Register sr;       // 0x08 §28.5.3
  Register dr;       // 0x0C §28.5.4 a write starts a transfer; a read takes the byte received
  Register crcpr;    // 0x10
  Register rxcrcr;   // 0x14
  Register txcrcr;   // 0x18
  Register i2scfgr;  // 0x1C
  Register i2spr;    // 0x20
};
constexpr std::uintptr_t spi1_base = 0x40013000u;
inline SpiRegisters& spi1() { return at<SpiRegisters>(spi1_base); }
// SPI6 exists on the STM32F42x/43x only (RM0090 Table 1), not on the F405; QEMU's model
// has it, and attaches a chip given with -device to it (tests/stm32f405).
constexpr std::uintptr_t spi6_base = 0x40015400u;
namespace spi_bits {
constexpr std::uint32_t cr1_cpha = 1u << 0;
constexpr std::uint32_t cr1_cpol = 1u << 1;
constexpr std::uint32_t cr1_mstr = 1u << 2;
constexpr std::uint32_t cr1_br(std::uint32_t divider_log2) {
  return (divider_log2 - 1u) << 3;
}  // f_PCLK / 2^n
constexpr std::uint32_t cr1_spe = 1u << 6;
constexpr std::uint32_t cr1_ssi = 1u << 8;
constexpr std::uint32_t cr1_ssm = 1u << 9;
constexpr std::uint32_t sr_rxne = 1u << 0;
constexpr std::uint32_t sr_txe = 1u << 1;
constexpr std::uint32_t sr_modf = 1u << 5;
constexpr std::uint32_t sr_ovr = 1u << 6;
constexpr std::uint32_t sr_bsy = 1u << 7;
}  // namespace spi_bits

// ---- USART1, 0x40011000, and USART2, 0x40004400 (RM0090 §30.6.8 register map) ----
struct UsartRegisters {
  Register sr;    // 0x00 §30.6.1
  Register dr;    // 0x04 §30.6.2
  Register brr;   // 0x08 §30.6.3 f_PCLK / baud rate, 12.4 fixed point (oversampling by 16)
  Register cr1;   // 0x0C §30.6.4
  Register cr2;   // 0x10 §30.6.5
  Register cr3;   // 0x14 §30.6.6
  Register gtpr;  // 0x18 §30.6.7
};
inline UsartRegisters& usart1() { return at<UsartRegisters>(0x40011000u); }
inline UsartRegisters& usart2() { return at<UsartRegisters>(0x40004400u); }
namespace usart_bits {
constexpr std::uint32_t sr_tc = 1u << 6;
constexpr std::uint32_t sr_txe = 1u << 7;
constexpr std::uint32_t cr1_te = 1u << 3;
constexpr std::uint32_t cr1_re = 1u << 2;
constexpr std::uint32_t cr1_ue = 1u << 13;
}  // namespace usart_bits

// The device's interrupts: positions 0..81 after the core's 16 exceptions (RM0090 §12.2,
// Table 61, "Vector table for STM32F405xx/07xx and STM32F415xx/17xx").
constexpr int device_interrupt_count = 82;

}  // namespace stm32f405
}  // namespace port
}  // namespace aloft
