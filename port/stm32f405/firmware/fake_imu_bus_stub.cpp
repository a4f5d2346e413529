// The replay image's bus until the ICM-42688-P fake chip lands (fake_imu_bus.hpp): a chip
// that answers WHO_AM_I with 0x47 and has nothing else, so the image finds its sensor,
// runs the pipeline loop, gets no samples and ends the stream on the MCU clock.
//
// TODO(lead, when the driver's fake chip lands): replace this file, in the cache variable
// ALOFT_STM32F405_FAKE_BUS_SOURCES, by a fake_imu_bus() over that chip holding a recorded
// throw's FIFO bytes, and the stm32f405_replay test's expected output by the host's
// `aloft replay --fifo` of the same bytes.
#include "fake_imu_bus.hpp"
#include "imu_source.hpp"
#include "spi1_imu_bus.hpp"

namespace aloft_stm32f405 {

namespace {

aloft::Status read(void*, std::uint8_t reg, std::uint8_t* data, std::uint16_t length) {
  for (std::uint16_t i = 0; i < length; ++i) data[i] = 0;
  if (reg == who_am_i_register && length > 0) data[0] = who_am_i_expected;
  return aloft::Status::ok;
}

aloft::Status write(void*, std::uint8_t, std::uint8_t) { return aloft::Status::ok; }

}  // namespace

aloft::ImuBus fake_imu_bus() {
  aloft::ImuBus bus;
  bus.read = read;
  bus.write = write;
  bus.now_us = aloft::port::stm32f405::ticks_in_us;
  return bus;
}

}  // namespace aloft_stm32f405
