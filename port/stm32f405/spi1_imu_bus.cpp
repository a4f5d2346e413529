// SPI1 as the IMU's bus: spi1_imu_bus.hpp. One transfer is one byte out and one in
// (RM0090 §28.3.5 "Data transmission and reception procedures": write DR when TXE is set,
// read DR when RXNE is set); a transaction ends when BSY is clear, before the chip select
// is released (§28.3.8).
#include "spi1_imu_bus.hpp"

#include <initializer_list>

#include "aloft_port/divide_u64.hpp"
#include "aloft_port/port.hpp"
#include "stm32f405_registers.hpp"

namespace aloft {
namespace port {
namespace stm32f405 {

namespace {

using namespace spi_bits;

constexpr std::uint32_t chip_select_pin = 4;  // PA4
constexpr std::uint32_t sck_pin = 5, miso_pin = 6, mosi_pin = 7;
SpiDevice imu_on_spi1 = {spi1_base, gpioa_base, chip_select_pin};
constexpr std::uint8_t read_bit = 0x80;
// A byte takes 8 SPI clocks, at most 64 processor clocks here; a flag that has not come
// after this many polls never will.
constexpr std::uint32_t max_polls = 10000u;

bool wait_for(const SpiRegisters& spi, std::uint32_t flag, bool set) {
  for (std::uint32_t polls = 0; polls < max_polls; ++polls) {
    if (((spi.sr & flag) != 0) == set) return true;
  }
  return false;
}

void select(const SpiDevice& device, bool selected) {
  // BSRR: the low half sets pins, the high half resets them; chip select is active low.
  at<GpioRegisters>(device.chip_select_port_base).bsrr =
      selected ? (1u << (device.chip_select_pin + 16u)) : (1u << device.chip_select_pin);
}

bool transfer(SpiRegisters& spi, std::uint8_t out, std::uint8_t& in) {
  if (!wait_for(spi, sr_txe, true)) return false;
  spi.dr = out;
  if (!wait_for(spi, sr_rxne, true)) return false;
  in = static_cast<std::uint8_t>(spi.dr);
  return true;
}

// Ends a transaction: the last byte fully out, then the chip released (also after a
// failed transfer, so the next transaction starts clean).
Status finish(const SpiDevice& device, bool transferred) {
  const bool idle = wait_for(at<SpiRegisters>(device.spi_base), sr_bsy, false);
  select(device, false);
  return transferred && idle ? Status::ok : Status::bus_error;
}

Status read(void* context, std::uint8_t reg, std::uint8_t* data, std::uint16_t length) {
  const SpiDevice& device = *static_cast<SpiDevice*>(context);
  SpiRegisters& spi = at<SpiRegisters>(device.spi_base);
  std::uint8_t ignored = 0;
  select(device, true);
  bool ok = transfer(spi, static_cast<std::uint8_t>(reg | read_bit), ignored);
  for (std::uint16_t i = 0; ok && i < length; ++i) ok = transfer(spi, 0x00, data[i]);
  return finish(device, ok);
}

Status write(void* context, std::uint8_t reg, std::uint8_t value) {
  const SpiDevice& device = *static_cast<SpiDevice*>(context);
  SpiRegisters& spi = at<SpiRegisters>(device.spi_base);
  std::uint8_t ignored = 0;
  select(device, true);
  const bool ok =
      transfer(spi, static_cast<std::uint8_t>(reg & ~read_bit), ignored) && transfer(spi, value, ignored);
  return finish(device, ok);
}

void set_pin_field(volatile std::uint32_t& reg, std::uint32_t pin, std::uint32_t bits, std::uint32_t value) {
  const std::uint32_t shift = pin * bits;
  const std::uint32_t mask = ((1u << bits) - 1u) << shift;
  reg = (reg & ~mask) | (value << shift);
}

}  // namespace

void spi_init_master(SpiRegisters& spi) {
  // Master, f_PCLK / 8, mode 3; SSM + SSI: NSS is driven in software (the chip select
  // is a GPIO), held high so the master never sees a mode fault.
  spi.cr1 = 0;
  spi.cr2 = 0;
  spi.cr1 = cr1_mstr | cr1_br(3) | cr1_cpol | cr1_cpha | cr1_ssm | cr1_ssi;
  spi.cr1 = spi.cr1 | cr1_spe;
}

// Once, at set-up: cold, so built for size (as init_clocks).
[[gnu::cold]] void spi1_init() {
  using namespace gpio_bits;
  rcc().ahb1enr = rcc().ahb1enr | rcc_bits::ahb1enr_gpioa;
  rcc().apb2enr = rcc().apb2enr | rcc_bits::apb2enr_spi1;
  GpioRegisters& gpio = gpioa();
  select(imu_on_spi1, false);  // high before it becomes an output: no glitch that selects the chip
  set_pin_field(gpio.moder, chip_select_pin, 2, mode_output);
  set_pin_field(gpio.ospeedr, chip_select_pin, 2, speed_very_high);
  for (std::uint32_t pin : {sck_pin, miso_pin, mosi_pin}) {
    set_pin_field(gpio.afr[0], pin, 4, af_spi1);
    set_pin_field(gpio.ospeedr, pin, 2, speed_very_high);
    set_pin_field(gpio.moder, pin, 2, mode_alternate);
  }
  spi_init_master(spi1());
}

// Every clock the board runs on is a whole number of MHz (16 MHz HSI, 168 MHz PLL): µs
// are ticks over ticks per µs, a division by a small number (aloft_port/divide_u64.hpp).
std::uint64_t ticks_in_us(void*) {
  std::uint32_t remainder = 0;
  return divide_u64(ticks(), ticks_per_second() / 1000000u, remainder);
}

ImuBus spi_imu_bus(SpiDevice& device) {
  ImuBus bus;
  bus.context = &device;
  bus.read = read;
  bus.write = write;
  bus.now_us = ticks_in_us;
  return bus;
}

ImuBus spi1_imu_bus() { return spi_imu_bus(imu_on_spi1); }

}  // namespace stm32f405
}  // namespace port
}  // namespace aloft
