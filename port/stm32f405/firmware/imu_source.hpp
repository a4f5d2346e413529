// Where the firmware's samples come from: the ICM-42688-P behind an aloft::ImuBus (SPI1
// on the board, a fake chip in the replay image).
//
// TODO(lead, when the ICM-42688-P FIFO driver lands in lib/): replace both functions
// with the driver (aloft/icm42688p_fifo.hpp): imu_bring_up -> its bring-up (soft reset,
// WHO_AM_I, configuration written and verified), imu_poll -> its poll (FIFO_COUNT, whole
// packets in one burst, decoded to ImuSample<float>). Until then imu_bring_up only reads
// WHO_AM_I and imu_poll delivers nothing.
#pragma once

#include <cstdint>

#include "aloft/imu_bus.hpp"
#include "aloft/imu_sample.hpp"

namespace aloft_stm32f405 {

constexpr std::uint8_t who_am_i_register = 0x75;  // ICM-42688-P datasheet §14.42 (bank 0)
constexpr std::uint8_t who_am_i_expected = 0x47;

// Finds the chip: Status::ok, sensor_not_found (who_am_i holds what was read instead of
// 0x47) or bus_error.
aloft::Status imu_bring_up(const aloft::ImuBus& bus, std::uint8_t& who_am_i);

// Up to `capacity` new samples into `out`; how many in `count`.
aloft::Status imu_poll(const aloft::ImuBus& bus, aloft::ImuSample<float>* out, std::uint16_t capacity,
                       std::uint16_t& count);

}  // namespace aloft_stm32f405
