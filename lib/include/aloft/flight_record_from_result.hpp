// From the onboard pipeline's result (aloft/onboard_pipeline.hpp) to a flight record
// (aloft/flight_record.hpp), and the two hashes a record carries so that a result can be
// matched to the tensor and settings it was checked with. Both hashes are CRC-32
// (aloft/crc32.hpp) over little-endian bytes, numbers as IEEE-754 binary32 whatever
// Scalar is (a firmware checks in float):
//   tensor hash:   Ixx, Iyy, Izz, Ixy, Ixz, Iyz of the tensor as given, kg·m² (24 bytes)
//   settings hash: live simulations K (u16), seed_every (u16), sensor_to_body w, x, y, z,
//                  flight.free_fall_below_m_s2, flight.landing_above_m_s2,
//                  flight.release_samples (u16), imu_position_known (u8, 0 or 1),
//                  imu_position_m x, y, z, bridge_gap_up_to_us (u32),
//                  end_flight_after_gap_us (u32)  (51 bytes)
#pragma once

#include <cstdint>

#include "aloft/crc32.hpp"
#include "aloft/flight_record.hpp"
#include "aloft/little_endian.hpp"
#include "aloft/onboard_pipeline.hpp"

namespace aloft {

template <typename Scalar>
std::uint32_t tensor_hash(const Mat3<Scalar>& tensor) {
  std::uint8_t bytes[24];
  const Scalar values[6] = {tensor(0, 0), tensor(1, 1), tensor(2, 2),
                            tensor(0, 1), tensor(0, 2), tensor(1, 2)};
  for (int i = 0; i < 6; ++i) le::put_f32(bytes + 4 * i, static_cast<float>(values[i]));
  return crc32(bytes, sizeof(bytes));
}

template <typename Scalar>
std::uint32_t settings_hash(const OnboardPipelineSettings<Scalar>& s, int live_simulations) {
  std::uint8_t bytes[51];
  std::uint8_t* p = bytes;
  const auto f32 = [&p](Scalar v) { le::put_f32(p, static_cast<float>(v)), p += 4; };
  le::put_u16(p, static_cast<std::uint16_t>(live_simulations)), p += 2;
  le::put_u16(p, s.check.seed_every), p += 2;
  const Quat<Scalar>& q = s.check.sensor_to_body;
  for (const Scalar v : {q.w(), q.x(), q.y(), q.z()}) f32(v);
  f32(s.check.flight.free_fall_below_m_s2);
  f32(s.check.flight.landing_above_m_s2);
  le::put_u16(p, s.check.flight.release_samples), p += 2;
  le::put_u8(p, s.imu_position_known ? 1 : 0), p += 1;
  for (int i = 0; i < 3; ++i) f32(s.imu_position_m[i]);
  le::put_u32(p, s.bridge_gap_up_to_us), p += 4;
  le::put_u32(p, s.end_flight_after_gap_us), p += 4;
  return crc32(bytes, static_cast<std::size_t>(p - bytes));
}

// The record of one finished flight; its sequence number is set when the ring stores
// it. `seeds` (optional) are the flight's first seeded simulations, in seeding order;
// at most flight_record_seeds of them are kept.
template <typename Scalar>
FlightRecord make_flight_record(const FlightResult<Scalar>& result, std::uint32_t tensor_hash_value,
                                std::uint32_t settings_hash_value, const SeedReport<Scalar>* seeds = nullptr,
                                std::uint32_t seed_count = 0) {
  FlightRecord r;
  r.flight_number = result.flight_number;
  r.release_us = result.release_us;
  r.landing_us = result.landing_us;
  r.samples = result.samples;
  r.gaps = result.gaps;
  r.clipped_samples = result.clipped_samples;
  r.landed = result.landed;
  r.turned = result.turned;
  r.imu_position_estimated = result.imu_position_estimated;
  r.comparisons = result.overall.count();
  r.rms_da_rad = static_cast<float>(result.overall.rms_da());
  r.rms_rel_err = static_cast<float>(result.overall.rms_relative_error());
  r.max_da_rad = static_cast<float>(result.overall.max_da());
  r.max_rel_err = static_cast<float>(result.overall.max_relative_error());
  r.seeds_stored =
      seeds == nullptr ? 0 : (seed_count < flight_record_seeds ? seed_count : flight_record_seeds);
  for (std::uint32_t i = 0; i < r.seeds_stored; ++i) {
    r.seeds[i].rms_da_rad = static_cast<float>(seeds[i].stats.rms_da());
    r.seeds[i].rms_rel_err = static_cast<float>(seeds[i].stats.rms_relative_error());
  }
  r.tensor_hash = tensor_hash_value;
  r.settings_hash = settings_hash_value;
  return r;
}

}  // namespace aloft
