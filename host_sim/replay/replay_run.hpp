// The replay itself: the firmware's onboard pipeline (aloft/onboard/onboard_pipeline.hpp,
// OnboardPipeline<float, 8>), fed a Recording sample by sample, exactly as a firmware
// feeds it from its sensor driver. It finds the flights itself. Times in ReplayResult
// are the pipeline's (µs after the recording's first sample); recording_time_s turns
// them into the recording's own base for reports.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "aloft/onboard/onboard_pipeline.hpp"
#include "common/body_file.hpp"
#include "replay/recording.hpp"

namespace aloft::host {

constexpr int kReplaySimulations = 8;  // K: live simulations, as the firmware example runs
using ReplayPipeline = OnboardPipeline<float, kReplaySimulations>;

// What the pipeline takes from the body file, in float as the firmware holds it.
struct ReplaySettings {
  Mat3<float> tensor_kg_m2 = Mat3<float>::Zero();  // body axes, about the centre of mass
  Quat<float> sensor_to_body = Quat<float>::Identity();
  std::optional<Vec3<float>> imu_position_m;  // body axes; none: the pipeline estimates it
  Rotor<float> rotor;                         // the body file's `rotor`; none: inertia 0
  // The gyro's first-order filter (tensor.gyro_filter_us): a property of the firmware that
  // logged the recording, not of the body; unless told, aloft's firmware's.
  std::uint16_t gyro_filter_us = TensorEstimatorSettings<float>{}.gyro_filter_us;
};

ReplaySettings replay_settings_from_body(const Body& body);

// The float tensor validated as the firmware validates it; throws Error naming `source`.
InertiaTensor<float> replay_inertia(const ReplaySettings& settings, const std::string& source);
OnboardPipelineSettings<float> pipeline_settings(const ReplaySettings& settings);

// One hole in the data: after the sample at at_us, the next came length_us later.
struct StreamGap {
  std::uint64_t at_us = 0;
  std::uint64_t length_us = 0;
};

struct ReplayResult {
  StreamCounts stream;  // as the pipeline counted them
  std::uint32_t invalid_samples = 0;
  std::uint64_t bytes_skipped = 0;
  std::uint32_t empty_reads = 0;
  std::uint32_t resyncs = 0;
  std::vector<StreamGap> gaps;
  std::vector<FlightResult<float>> flights;
  std::int64_t t0_us = 0;                // the recording's first sample in its own time base
  std::uint16_t gyro_filter_us = 0;      // the filter the pipeline assumed (ReplaySettings)
  bool gyro_filter_from_option = false;  // told (--gyro-filter-us), not the firmware's default
};

// Runs the pipeline over every sample; throws Error naming the recording and the sample
// if the pipeline refuses one (a reader lets none through that it would refuse).
ReplayResult run_replay(const ReplaySettings& settings, const std::string& body_source,
                        const Recording& recording);

// A pipeline time (µs after the first sample) in the recording's own base, seconds,
// exact to the microsecond.
double recording_time_s(const ReplayResult& result, std::uint64_t pipeline_us);

}  // namespace aloft::host
