// Replay firmware: the onboard pipeline (aloft::OnboardPipeline<float, 8>, as `aloft
// replay` runs it) fed a recording stored in flash (stored_recording.hpp) sample by sample,
// as a firmware feeds it from its sensor driver. Prints each flight's result
// (flight_lines.hpp); tests/target compares them with the host's replay of the same CSV.
#include <cstdint>
#include <optional>

#include "aloft/onboard/onboard_pipeline.hpp"
#include "aloft_port/report_writer.hpp"
#include "flight_lines.hpp"
#include "stored_recording.hpp"

namespace {

namespace stored = aloft_replay_example;
using Pipeline = aloft::OnboardPipeline<float, 8>;

// Static storage, so the pipeline's whole memory shows in .bss (no heap).
std::optional<Pipeline> pipeline;
aloft::FlightResult<float> flight;

aloft::OnboardPipelineSettings<float> stored_settings() {
  aloft::OnboardPipelineSettings<float> settings;
  const float* q = stored::stored_sensor_to_body_wxyz;
  settings.check.sensor_to_body = aloft::Quat<float>(q[0], q[1], q[2], q[3]);
  settings.imu_position_known = stored::stored_imu_position_known;
  const float* r = stored::stored_imu_position_m;
  settings.imu_position_m = aloft::Vec3<float>(r[0], r[1], r[2]);
  return settings;
}

aloft::ImuSample<float> sample_at(unsigned i) {
  const stored::StoredSample& s = stored::stored_samples[i];
  aloft::ImuSample<float> sample;
  sample.t_us = s.t_us;
  sample.gyro_rad_s = aloft::Vec3<float>(s.gyro_rad_s[0], s.gyro_rad_s[1], s.gyro_rad_s[2]);
  sample.accel_m_s2 = aloft::Vec3<float>(s.accel_m_s2[0], s.accel_m_s2[1], s.accel_m_s2[2]);
  sample.flags = s.flags;
  return sample;
}

void write_finished_flights(aloft::port::ReportWriter& out) {
  while (pipeline->take_finished_flight(flight))
    aloft_flight_lines::write_flight_lines(out, flight, stored::stored_t0_us);
}

}  // namespace

int main() {
  aloft::port::init();
  aloft::port::ReportWriter out;
  out.text("aloft replay firmware: OnboardPipeline<float, 8>, recording ")
      .text(stored::stored_recording_name)
      .line();
  aloft::Mat3<float> tensor;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) tensor(r, c) = stored::stored_inertia_kg_m2[r][c];
  }
  aloft::InertiaTensor<float> inertia;
  const aloft::Status made = aloft::InertiaTensor<float>::make_from_tensor(tensor, inertia);
  if (made != aloft::Status::ok) {
    out.text("inertia tensor rejected: ").text(aloft::describe(made)).line();
    return 1;
  }
  pipeline.emplace(inertia, stored_settings());
  for (unsigned i = 0; i < stored::stored_sample_count; ++i) {
    const aloft::Status pushed = pipeline->push(sample_at(i));
    if (pushed != aloft::Status::ok) {
      out.text("sample ").integer(i + 1).text(": ").text(aloft::describe(pushed)).line();
      return 1;
    }
    write_finished_flights(out);
  }
  pipeline->finish();
  write_finished_flights(out);
  out.text("stream_samples ").integer(pipeline->stream().samples).line();
  out.text("stream_gaps ").integer(pipeline->stream().gaps).line();
  return 0;
}
