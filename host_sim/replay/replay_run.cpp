#include "replay/replay_run.hpp"

#include <cmath>
#include <memory>

#include "common/commands.hpp"

namespace aloft::host {

ReplaySettings replay_settings_from_body(const Body& body) {
  ReplaySettings s;
  s.tensor_kg_m2 = body.inertia.tensor().cast<float>();
  s.sensor_to_body = body.imu_to_body.cast<float>();
  if (body.imu_position_m) s.imu_position_m = body.imu_position_m->cast<float>();
  if (body.rotor) {
    // Normalised again in float: the double unit vector, rounded, is a hair off unit.
    s.rotor.axis = body.rotor->axis.cast<float>().normalized();
    s.rotor.inertia_kg_m2 = static_cast<float>(body.rotor->inertia_kg_m2);
  }
  return s;
}

InertiaTensor<float> replay_inertia(const ReplaySettings& settings, const std::string& source) {
  InertiaTensor<float> inertia;
  const Status made = InertiaTensor<float>::make_from_tensor(settings.tensor_kg_m2, inertia);
  if (made != Status::ok) throw Error(source + ": inertia tensor in single precision: " + describe(made));
  return inertia;
}

OnboardPipelineSettings<float> pipeline_settings(const ReplaySettings& settings) {
  OnboardPipelineSettings<float> p;
  p.check.sensor_to_body = settings.sensor_to_body;
  p.imu_position_known = settings.imu_position_m.has_value();
  if (settings.imu_position_m) p.imu_position_m = *settings.imu_position_m;
  p.rotor = settings.rotor;
  p.tensor.gyro_filter_us = settings.gyro_filter_us;
  return p;
}

ReplayResult run_replay(const ReplaySettings& settings, const std::string& body_source,
                        const Recording& recording) {
  ReplayResult result;
  result.invalid_samples = recording.invalid_samples;
  result.bytes_skipped = recording.bytes_skipped;
  result.empty_reads = recording.empty_reads;
  result.resyncs = recording.resyncs;
  result.t0_us = std::llround(recording.t0_s * 1e6);
  result.gyro_filter_us = settings.gyro_filter_us;
  // The pipeline is large (K simulations); on the heap rather than the stack.
  auto pipeline =
      std::make_unique<ReplayPipeline>(replay_inertia(settings, body_source), pipeline_settings(settings));
  FlightResult<float> flight;
  for (std::size_t i = 0; i < recording.samples.size(); ++i) {
    const ImuSample<float>& sample = recording.samples[i];
    const Status pushed = pipeline->push(sample);
    if (pushed != Status::ok) {
      throw Error(recording.path + ": sample " + std::to_string(i + 1) + ": " + describe(pushed));
    }
    if (i > 0 && sample.gap_before()) {
      const std::uint64_t before = recording.samples[i - 1].t_us;
      result.gaps.push_back({before, sample.t_us - before});
    }
    while (pipeline->take_finished_flight(flight)) result.flights.push_back(flight);
  }
  pipeline->finish();
  while (pipeline->take_finished_flight(flight)) result.flights.push_back(flight);
  result.stream = pipeline->stream();
  return result;
}

double recording_time_s(const ReplayResult& result, std::uint64_t pipeline_us) {
  return static_cast<double>(result.t0_us + static_cast<std::int64_t>(pipeline_us)) / 1e6;
}

}  // namespace aloft::host
