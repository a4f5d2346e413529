// The replay image's bus (main.cpp built with ALOFT_STM32F405_FAKE_BUS): an
// ICM-42688-P fake chip in place of SPI1 that plays a recorded throw's FIFO bytes
// (fake_imu_bus.cpp, replay_throw.hpp), so the whole pipeline (driver -> release ->
// check -> result) runs on known data under QEMU.
#pragma once

#include "aloft/sensor/imu_bus.hpp"

namespace aloft_stm32f405 {

aloft::ImuBus fake_imu_bus();

}  // namespace aloft_stm32f405
