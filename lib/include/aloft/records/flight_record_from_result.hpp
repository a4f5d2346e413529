// From the onboard pipeline's result (aloft/onboard/onboard_pipeline.hpp) to a flight record
// (aloft/records/flight_record.hpp), and the tensor hash a record carries so that a result can
// be matched to the tensor it was checked with: CRC-32 (aloft/records/crc32.hpp) of Ixx, Iyy,
// Izz, Ixy, Ixz, Iyz of the tensor as given, kg·m², little-endian IEEE-754 binary32 whatever
// Scalar is (24 bytes). The settings hash is aloft/records/settings_hash.hpp's.
#pragma once

#include <cstdint>

#include "aloft/cold_path.hpp"
#include "aloft/records/crc32.hpp"
#include "aloft/records/flight_record.hpp"
#include "aloft/onboard/onboard_pipeline.hpp"
#include "aloft/records/little_endian.hpp"
#include "aloft/records/settings_hash.hpp"

namespace aloft {

template <typename Scalar>
std::uint32_t tensor_hash(const Mat3<Scalar>& tensor) {
  std::uint8_t bytes[24];
  const Scalar values[6] = {tensor(0, 0), tensor(1, 1), tensor(2, 2),
                            tensor(0, 1), tensor(0, 2), tensor(1, 2)};
  for (int i = 0; i < 6; ++i) le::put_f32(bytes + 4 * i, static_cast<float>(values[i]));
  return crc32(bytes, sizeof(bytes));
}

// The record of one finished flight, with its first seeds (FlightResult::first_seeds);
// its sequence number is set when the ring stores it.
static_assert(kept_first_seeds == flight_record_seeds, "a record holds the seeds the check keeps");
template <typename Scalar>
FlightRecord make_flight_record(const FlightResult<Scalar>& result, std::uint32_t tensor_hash_value,
                                std::uint32_t settings_hash_value) {
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
      result.first_seed_count < flight_record_seeds ? result.first_seed_count : flight_record_seeds;
  for (std::uint32_t i = 0; i < r.seeds_stored; ++i) {
    r.seeds[i].rms_da_rad = static_cast<float>(result.first_seeds[i].rms_da_rad);
    r.seeds[i].rms_rel_err = static_cast<float>(result.first_seeds[i].rms_rel_err);
  }
  r.tensor_hash = tensor_hash_value;
  r.settings_hash = settings_hash_value;
  return r;
}

}  // namespace aloft
