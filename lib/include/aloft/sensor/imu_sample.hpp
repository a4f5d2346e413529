// One IMU sample as it flows from the sensor to the onboard check: the one type that a
// driver (aloft/sensor/icm42688p_fifo.hpp), a recording read on the host (`aloft replay`) and the
// onboard pipeline share. Units and axes are fixed here once:
//   - t_us: the sample's time stamp in microseconds, 64-bit, unwrapped and monotonic
//     (strictly increasing from one sample to the next). The check takes every dt from
//     these stamps, never from a nominal rate.
//   - gyro_rad_s, accel_m_s2: sensor axes, rad/s and m/s² (specific force: what an
//     accelerometer reads, +9.81 m/s² up when it rests on a table, 0 in free fall when it
//     sits at the centre of mass).
//   - flags: what the source knows and the numbers cannot say (ImuSampleFlag bits).
//   - rotor_rad_s: the speed of the body's rotor, where it has one and the source gives it.
#pragma once

#include <cstdint>

#include "aloft/dynamics/rotation.hpp"

namespace aloft {

// Bits of ImuSample::flags.
enum ImuSampleFlag : std::uint8_t {
  // Data were lost between the previous sample and this one (a FIFO overflow, a dropped
  // packet, a hole in a log). The gap's length is the difference of the time stamps.
  imu_gap_before = 1u << 0,
  // At least one gyro (accelerometer) axis sat at its full-scale limit: the true value
  // may be larger, so the sample is not a measurement of that axis.
  imu_gyro_clipped = 1u << 1,
  imu_accel_clipped = 1u << 2,
  // The sample carries the rotor's speed (ImuSample::rotor_rad_s; aloft/dynamics/rotor.hpp).
  imu_rotor_speed = 1u << 3,
};

template <typename Scalar>
struct ImuSample {
  std::uint64_t t_us = 0;
  Vec3<Scalar> gyro_rad_s = Vec3<Scalar>::Zero();
  Vec3<Scalar> accel_m_s2 = Vec3<Scalar>::Zero();
  std::uint8_t flags = 0;
  // The body's rotor's speed relative to the body, rad/s (SPEC §3 rotor_rad_s), valid when
  // flags has imu_rotor_speed.
  Scalar rotor_rad_s = Scalar(0);

  bool gap_before() const { return (flags & imu_gap_before) != 0; }
  bool has_rotor_speed() const { return (flags & imu_rotor_speed) != 0; }
  bool clipped() const { return (flags & (imu_gyro_clipped | imu_accel_clipped)) != 0; }
};

}  // namespace aloft
