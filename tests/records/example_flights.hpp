// The flights behind examples/flight_records.bin: throws of the asymmetric top of the
// core tests (principal moments 0.01, 0.02, 0.03 kg·m², flipping about its intermediate
// axis: exact_tops.hpp), sampled at 1 kHz with the IMU at the centre of mass, run
// through the onboard pipeline in float as the firmware runs it, each result stored
// through the record ring on a file-backed NOR flash (3 blocks of 1 KiB). The throws:
//   0  a clean throw, right tensor
//   1  the same with a 4 ms hole (a gap) and 3 clipped samples
//   2  a drop from rest: no rotation, nothing to say about the tensor
//   3  a throw checked with a tensor whose smallest moment is 15 % too large
//   4  a throw the recording ends in (not landed)
#pragma once

#include <cstdint>
#include <string>

#include "aloft/records/flight_record_from_result.hpp"
#include "aloft/records/record_ring.hpp"
#include "exact_tops.hpp"
#include "file_block_device.hpp"

namespace aloft::test {

constexpr std::uint32_t example_block_size = 1024;
constexpr std::uint32_t example_block_count = 3;
const aloft_test::AsymmetricTop example_top{0.01, 0.02, 0.03, 8.0, 5.0, 0.3};

struct ExampleThrow {
  bool spin = true;
  bool gap = false;
  int clipped = 0;
  bool lands = true;
};

// Rest, release, 800 ms of flight, landing, rest; samples pushed into the pipeline.
template <typename Pipeline>
void push_throw(Pipeline& pipeline, std::uint64_t& t_us, const ExampleThrow& how) {
  const auto push = [&](const Vec3<float>& gyro, const Vec3<float>& accel, std::uint8_t flags) {
    ImuSample<float> s;
    s.t_us = t_us;
    s.gyro_rad_s = gyro;
    s.accel_m_s2 = accel;
    s.flags = flags;
    static_cast<void>(pipeline.push(s));
    t_us += 1000;
  };
  const Vec3<float> rest(0.0f, 0.0f, 9.81f);
  for (int k = 0; k < 300; ++k) push(Vec3<float>::Zero(), rest, 0);
  const std::uint64_t release_us = t_us;
  for (int k = 0; k < 800; ++k) {
    if (how.gap && k == 400) t_us += 4000;  // 4 samples lost; the motion goes on
    const std::uint8_t flags =
        static_cast<std::uint8_t>((how.gap && k == 400 ? imu_gap_before : 0) |
                                  (k >= 500 && k < 500 + how.clipped ? imu_gyro_clipped : 0));
    const Vec3<float> gyro =
        how.spin ? Vec3<float>(example_top.omega(static_cast<double>(t_us - release_us) * 1e-6).cast<float>())
                 : Vec3<float>::Zero();
    push(gyro, Vec3<float>::Zero(), flags);
  }
  if (!how.lands) return;
  for (int k = 0; k < 5; ++k) push(Vec3<float>::Zero(), Vec3<float>(0.0f, 0.0f, 45.0f), 0);
  for (int k = 0; k < 300; ++k) push(Vec3<float>::Zero(), rest, 0);
}

// Runs one throw through a fresh pipeline for the given tensor and appends its record.
inline Status append_example_throw(RecordRing& ring, const ExampleThrow& how, double scale_i1,
                                   std::uint64_t& t_us, std::uint32_t& flight_number) {
  InertiaTensor<float> inertia;
  const Vec3<float> moments(static_cast<float>(example_top.i1 * scale_i1), static_cast<float>(example_top.i2),
                            static_cast<float>(example_top.i3));
  Status s = InertiaTensor<float>::make_from_principal(moments, Quat<float>::Identity(), inertia);
  if (s != Status::ok) return s;
  OnboardPipelineSettings<float> settings;
  settings.imu_position_known = true;
  OnboardPipeline<float, 8> pipeline(inertia, settings);
  push_throw(pipeline, t_us, how);
  pipeline.finish();
  FlightResult<float> result;
  if (!pipeline.take_finished_flight(result)) return Status::not_airborne;
  result.flight_number = flight_number++;
  FlightRecord record = make_flight_record(result, tensor_hash(inertia.tensor()), settings_hash(settings, 8));
  return ring.append(record);
}

// Writes the example dump to `path`; ok when every throw was stored.
inline Status write_example_dump(const std::string& path) {
  FileBlockDevice flash(path, example_block_size, example_block_count);
  RecordRing ring(flash.device());
  Status s = ring.mount();
  std::uint64_t t_us = 1000000;
  std::uint32_t flight = 0;
  const ExampleThrow throws[5] = {
      {}, {true, true, 3, true}, {false, false, 0, true}, {}, {true, false, 0, false}};
  for (int i = 0; i < 5 && s == Status::ok; ++i)
    s = append_example_throw(ring, throws[i], i == 3 ? 1.15 : 1.0, t_us, flight);
  return s == Status::ok && flash.violations() != 0 ? Status::corrupt_data : s;
}

}  // namespace aloft::test
