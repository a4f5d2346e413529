// The IMU's bus on an STM32F405 flight controller: SPI1 at register level (RM0090 §28)
// with the chip select on a GPIO, as an aloft::ImuBus (aloft/sensor/imu_bus.hpp) for the
// ICM-42688-P driver. Pins (the common F405 flight-controller layout; check the board's
// schematic): PA5 SCK, PA6 MISO, PA7 MOSI (alternate function 5), PA4 chip select
// (push-pull output, active low). SPI mode 3 (CPOL = 1, CPHA = 1), 8 bits, MSB first,
// f_PCLK2 / 8: 10.5 MHz at 168 MHz, 2 MHz on the HSI fallback, both within the
// ICM-42688-P's 24 MHz.
//
// Every wait on a status flag is bounded: a bus that never answers is Status::bus_error,
// never a hang. Under QEMU's netduinoplus2 SPI1 is modelled with nothing attached (every
// byte received is 0x00) and GPIO is not (the chip-select writes are dropped, harmlessly).
#pragma once

#include "aloft/sensor/imu_bus.hpp"
#include "stm32f405_registers.hpp"

namespace aloft {
namespace port {
namespace stm32f405 {

// Clocks GPIOA and SPI1, sets up the pins and SPI1 as master with software slave
// management, and leaves the chip deselected. Call after port::init().
void spi1_init();

// The bus over SPI1: a read sends reg | 0x80 (InvenSense's read bit) and then clocks in
// `length` bytes in the same transaction; a write sends reg and the value; now_us is
// port::ticks() in microseconds.
ImuBus spi1_imu_bus();

// The same over another SPI block and chip select (the bus's context): for a check
// under QEMU, which attaches chips to its last SPI bus only.
struct SpiDevice {
  std::uintptr_t spi_base;               // e.g. spi1_base
  std::uintptr_t chip_select_port_base;  // e.g. gpioa_base
  std::uint32_t chip_select_pin;
};
void spi_init_master(SpiRegisters& spi);
ImuBus spi_imu_bus(SpiDevice& device);

// The buses' now_us: port::ticks() in whole microseconds (the context is unused), for
// any other ImuBus on this board (the replay image's fake chip).
std::uint64_t ticks_in_us(void* unused);

}  // namespace stm32f405
}  // namespace port
}  // namespace aloft
