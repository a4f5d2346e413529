// The recorded throw the replay image's fake chip plays (fake_imu_bus.cpp), and the body
// it was thrown with. The definition (replay_throw.cpp in the build folder) is written at
// build time by port/host_tools/make_fifo_throw.cpp from examples/throw_imu.csv and
// examples/throw_body.json, which also writes the same packets as a FIFO file for the
// host's `aloft replay --fifo` (tests/stm32f405 compares the two results).
#pragma once

#include <cstdint>

#include "aloft/dynamics/inertia_tensor.hpp"
#include "icm42688p_packet_encoder.hpp"

namespace aloft_stm32f405 {

constexpr std::uint32_t replay_odr_hz = 1000;  // the driver's default rate, as the CSV's

extern const aloft_test::ChipSample replay_chip_samples[];  // raw counts, one per period
extern const std::uint32_t replay_chip_sample_count;
extern const float replay_inertia_kg_m2[3][3];  // body axes, about the centre of mass
// That tensor as the host's replay decomposes it (aloft::host::replay_inertia).
extern const aloft::InertiaTensorParts<float> replay_inertia_parts;
extern const float replay_sensor_to_body_wxyz[4];  // imu.rotation
extern const bool replay_imu_position_known;       // imu.position given
extern const float replay_imu_position_m[3];

}  // namespace aloft_stm32f405
