// The replay image's bus (main.cpp built with ALOFT_STM32F405_FAKE_BUS): an
// ICM-42688-P fake chip in place of SPI1 that plays a recorded throw's FIFO bytes, so the
// whole pipeline (driver -> release -> check -> result) runs on known data under QEMU.
//
// TODO(lead, when the ICM-42688-P driver and its fake chip land): define fake_imu_bus()
// in a .cpp over the fake chip (with the recorded bytes in flash) and name that .cpp in
// the CMake cache variable ALOFT_STM32F405_FAKE_BUS_SOURCES; the aloft_stm32f405_replay
// image and the stm32f405_replay test then appear (port/stm32f405/firmware/CMakeLists.txt,
// tests/stm32f405/CMakeLists.txt).
#pragma once

#include "aloft/imu_bus.hpp"

namespace aloft_stm32f405 {

aloft::ImuBus fake_imu_bus();

}  // namespace aloft_stm32f405
