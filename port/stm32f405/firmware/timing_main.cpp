// The timing image behind footprint.json's instructions_per_sample: the onboard pipeline
// (release detection + onboard check at K = 8, flight_settings.hpp) fed a synthetic throw
// computed on the fly (1 kHz: 200 samples at rest, then free fall with the body
// tumbling), with the SysTick counts that measure_footprint.cmake converts to
// instructions.
//
// Built twice: as is, and with ALOFT_STM32F405_TIMING_BASELINE, where each sample is
// only consumed trivially. The difference of the two loop timings, per sample, is the
// pipeline's cost; the samples timed are those after the K-th simulation is seeded, so
// all K are live.
//
// TODO(lead, when the ICM-42688-P FIFO driver lands): feed the pipeline from the driver
// polling a fake chip that holds this throw as FIFO packets, and give the baseline the
// same bus reads without decoding, so that "decode" is in the difference too.
#include <cstdint>
#include <optional>

#include "aloft_port/port.hpp"
#include "aloft_port/report_writer.hpp"
#include "../../cortex_m/icount_calibration.hpp"
#include "flight_settings.hpp"

namespace {

constexpr unsigned rest_samples = 200;
constexpr unsigned samples = 1200;
// Release is detected after release_samples (3) free-fall samples; seeds then start every
// N = 10 airborne samples. Timing starts well after the K-th seed.
constexpr unsigned first_timed_sample = rest_samples + 3 + aloft_stm32f405::live_simulations * 10 + 20;

#if !defined(ALOFT_STM32F405_TIMING_BASELINE)
std::optional<aloft_stm32f405::Pipeline> pipeline;
#else
volatile float sample_sink;
#endif

aloft::ImuSample<float> synthetic_sample(unsigned i) {
  aloft::ImuSample<float> s;
  s.t_us = 1000u * static_cast<std::uint64_t>(i);
  const float wobble = 0.01f * static_cast<float>(i % 7u);
  s.gyro_rad_s = aloft::Vec3<float>(3.0f + wobble, 5.0f - wobble, 7.0f);
  s.accel_m_s2 =
      i < rest_samples ? aloft::Vec3<float>(0.0f, 0.0f, 9.80665f) : aloft::Vec3<float>(0.1f, 0.0f, 0.2f);
  return s;
}

}  // namespace

int main() {
  aloft::port::init();
  aloft::port::ReportWriter out;
  aloft::port::report_calibration(out);
#if !defined(ALOFT_STM32F405_TIMING_BASELINE)
  aloft::InertiaTensor<float> inertia;
  if (aloft_stm32f405::make_inertia(inertia) != aloft::Status::ok) {
    out.text("inertia tensor rejected").line();
    return 1;
  }
  pipeline.emplace(inertia, aloft_stm32f405::pipeline_settings());
#endif
  std::uint64_t start = 0;
  for (unsigned i = 0; i < samples; ++i) {
    if (i == first_timed_sample) start = aloft::port::ticks();
    const aloft::ImuSample<float> sample = synthetic_sample(i);
#if !defined(ALOFT_STM32F405_TIMING_BASELINE)
    if (i == first_timed_sample && !pipeline->airborne()) {
      out.text("not airborne when the timing starts").line();
      return 1;
    }
    if (pipeline->push(sample) != aloft::Status::ok) {
      out.text("sample ").integer(i).text(" rejected").line();
      return 1;
    }
#else
    sample_sink = sample.gyro_rad_s.x() + sample.accel_m_s2.z() + static_cast<float>(sample.t_us & 1u);
#endif
  }
  const std::uint64_t steady_ticks = aloft::port::ticks() - start;
#if !defined(ALOFT_STM32F405_TIMING_BASELINE)
  if (!pipeline->airborne()) {
    out.text("the flight ended inside the timed samples").line();
    return 1;
  }
#endif
  out.text("steady_updates ").integer(samples - first_timed_sample).line();
  out.text("steady_ticks ").integer(static_cast<std::int64_t>(steady_ticks)).line();
  return 0;
}
