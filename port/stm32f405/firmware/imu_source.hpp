// Where the firmware's samples come from: the ICM-42688-P behind an aloft::ImuBus (SPI1
// on the board, a fake chip in the replay image), through the board-independent driver
// (aloft/sensor/icm42688p_driver.hpp) at its default settings: 1 kHz, time stamps on the PLL.
#pragma once

#include <cstdint>

#include "aloft/sensor/icm42688p_driver.hpp"
#include "aloft/sensor/imu_bus.hpp"
#include "aloft/sensor/imu_sample.hpp"

namespace aloft_stm32f405 {

constexpr std::uint8_t who_am_i_register = aloft::icm42688p::bank0::who_am_i;
constexpr std::uint8_t who_am_i_expected = aloft::icm42688p::kWhoAmIValue;

// The driver's bring-up (soft reset, WHO_AM_I, configuration written and verified, FIFO
// flushed): Status::ok, sensor_not_found (who_am_i holds what was read instead of 0x47),
// register_not_kept or bus_error.
aloft::Status imu_bring_up(const aloft::ImuBus& bus, std::uint8_t& who_am_i);

// One driver poll: each new sample (one burst at most) goes to `sink` as it is decoded,
// so no batch of samples is held in RAM between the driver and the pipeline.
aloft::Status imu_poll(const aloft::icm42688p::SampleSink<float>& sink);

// What the driver met since the bring-up.
const aloft::icm42688p::DriverCounters& imu_counters();

// The MCU's µs clock of the bus the driver was brought up on.
std::uint64_t imu_bus_now_us();

}  // namespace aloft_stm32f405
