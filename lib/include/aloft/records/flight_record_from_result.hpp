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

// The tensor estimate as a version 3 record keeps it (the quaternion with w >= 0).
template <typename Scalar>
FlightRecordTensor record_tensor(const TensorEstimate<Scalar>& e) {
  FlightRecordTensor t;
  t.determined = e.determined;
  t.absolute = e.absolute;
  t.note = static_cast<std::uint8_t>(e.note);
  const Scalar sign = e.axes.w() < Scalar(0) ? Scalar(-1) : Scalar(1);
  const Scalar xyz[3] = {e.axes.x(), e.axes.y(), e.axes.z()};
  for (int i = 0; i < 3; ++i) {
    t.principal[i] = static_cast<float>(e.principal(i));
    t.axes_xyz[i] = static_cast<float>(sign * xyz[i]);
    t.principal_95[i] = static_cast<float>(e.principal_95(i));
    t.axes_95_rad[i] = static_cast<float>(e.axes_95_rad(i));
  }
  t.ratios_95[0] = static_cast<float>(e.ratios_95[0]);
  t.ratios_95[1] = static_cast<float>(e.ratios_95[1]);
  return t;
}

// The record of one finished flight, with its tensor estimate (FlightResult::tensor); its
// sequence number is set when the ring stores it. (Version 3 keeps no first seeds.)
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
  r.tensor = record_tensor(result.tensor);
  r.tensor_hash = tensor_hash_value;
  r.settings_hash = settings_hash_value;
  return r;
}

}  // namespace aloft
