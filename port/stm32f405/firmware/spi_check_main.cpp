// A check of the IMU bus's SPI code (../spi1_imu_bus.cpp) against a chip that answers.
// QEMU attaches a chip given with -device (here a Micron N25Q128 SPI NOR flash) to the
// first free SPI bus it finds, which on netduinoplus2 is the last SPI block it models
// (SPI6 at 0x40015400), not SPI1; so the check runs the same bus functions on SPI6.
// Reading "register 0x1F" sends 0x1F | 0x80 = 0x9F, the flash's READ JEDEC ID command,
// and clocks in its answer in the same transaction (what the bytes are under QEMU, whose
// SPI model also clocks on reads of DR: tests/stm32f405/CMakeLists.txt). Without a chip
// the bytes read 0x00. Exit status 0 when the bus call succeeded.
#include <cstdint>

#include "aloft_port/port.hpp"
#include "aloft_port/report_writer.hpp"
#include "spi1_imu_bus.hpp"

namespace stm32 = aloft::port::stm32f405;

int main() {
  aloft::port::init();
  stm32::spi_init_master(stm32::at<stm32::SpiRegisters>(stm32::spi6_base));
  stm32::SpiDevice flash = {stm32::spi6_base, stm32::gpioa_base, 15};  // chip select: GPIO not modelled
  const aloft::ImuBus bus = stm32::spi_imu_bus(flash);
  std::uint8_t id[3] = {0, 0, 0};
  const aloft::Status read = bus.read(bus.context, 0x1F, id, sizeof(id));
  aloft::port::ReportWriter out;
  out.text("SPI read of 0x1F: ").text(aloft::describe(read)).text(", bytes");
  for (std::uint8_t byte : id) out.text(" ").hex_byte(byte);
  out.line();
  return read == aloft::Status::ok ? 0 : 1;
}
