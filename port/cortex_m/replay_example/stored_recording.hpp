// A recording stored in flash for the replay firmware: the IMU samples exactly as
// `aloft replay --imu` hands them to the pipeline (float, µs after the first sample,
// flags), and the settings it takes from the body file. The definition
// (stored_recording.cpp in the build folder) is written at build time by
// port/host_tools/make_replay_source.cpp, through the host's own reader of the CSV.
#pragma once

#include <cstdint>

namespace aloft_replay_example {

struct StoredSample {
  std::uint32_t t_us;  // after the first sample
  float gyro_rad_s[3];
  float accel_m_s2[3];
  std::uint8_t flags;  // aloft::ImuSampleFlag bits
};

extern const char stored_recording_name[];
extern const std::int64_t stored_t0_us;            // the first sample in the CSV's time base
extern const float stored_inertia_kg_m2[3][3];     // body axes, about the centre of mass
extern const float stored_sensor_to_body_wxyz[4];  // imu.rotation
extern const bool stored_imu_position_known;       // imu.position given
extern const float stored_imu_position_m[3];
extern const StoredSample stored_samples[];
extern const unsigned stored_sample_count;

}  // namespace aloft_replay_example
