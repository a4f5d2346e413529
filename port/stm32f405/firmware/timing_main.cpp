// The timing image behind footprint.json's instructions_per_sample: the onboard pipeline
// (release detection + onboard check at K = 8, flight_settings.hpp) fed a synthetic throw
// computed on the fly (1 kHz: 200 samples at rest, then free fall with the body
// tumbling), with the SysTick counts that measure_footprint.cmake converts to
// instructions.
//
// The samples come through the ICM-42688-P driver (aloft/sensor/icm42688p_driver.hpp) polling
// the tests' fake chip (port/fakes/fake_icm42688p.hpp), which makes the throw's packets:
// each loop step moves the chip's clock by one period (one packet) and polls once.
//
// Built twice: as is, and with ALOFT_STM32F405_TIMING_BASELINE, where each step makes
// the same bus reads as the driver's poll (INT_STATUS + FIFO_COUNT, then the packet's
// burst) and consumes the bytes trivially, without decoding. The difference of the two
// loop timings, per sample, is the cost of decode + detection + check; the samples timed
// are those after the K-th simulation is seeded, so all K are live.
#include <cstdint>
#include <optional>

#include "../../cortex_m/icount_calibration.hpp"
#include "aloft/sensor/icm42688p_driver.hpp"
#include "aloft_port/port.hpp"
#include "aloft_port/report_writer.hpp"
#include "fake_icm42688p.hpp"
#include "flight_settings.hpp"

namespace {

constexpr unsigned rest_samples = 200;
constexpr unsigned samples = 1200;
// Release is found a few samples into free fall (3 are allowed for); seeds then start every
// N = 10 airborne samples. Timing starts well after the K-th seed.
constexpr unsigned first_timed_sample = rest_samples + 3 + aloft_stm32f405::live_simulations * 10 + 20;

constexpr std::uint64_t period_us = 1000;  // the driver's default 1 kHz

// Sample i of the throw in raw counts (±2000 °/s: 16.4 LSB/(°/s); ±16 g: 2048 LSB/g):
// rad/s 3, 5, 7 with a wobble; at rest 1 g on z, then free fall (0.1, 0, 0.2) m/s².
aloft_test::ChipSample synthetic_sample(std::uint32_t i) {
  const float lsb_per_rad_s = 16.4f * 57.2957795f, lsb_per_m_s2 = 2048.0f / 9.80665f;
  const float wobble = 0.01f * static_cast<float>(i % 7u);
  const float gyro[3] = {3.0f + wobble, 5.0f - wobble, 7.0f};
  const float accel[3] = {i < rest_samples ? 0.0f : 0.1f, 0.0f, i < rest_samples ? 9.80665f : 0.2f};
  aloft_test::ChipSample s;
  for (int a = 0; a < 3; ++a) {
    s.gyro[a] = static_cast<std::int16_t>(gyro[a] * lsb_per_rad_s + 0.5f);
    s.accel[a] = static_cast<std::int16_t>(accel[a] * lsb_per_m_s2 + 0.5f);
  }
  return s;
}

aloft_test::FakeIcm42688p chip(synthetic_sample);

// The MCU clock: 1 µs per read during the bring-up (its bounded waits end), then still
// between the loop's steps, so each step makes exactly one packet in both images.
std::uint64_t mcu_us = 0;
bool clock_ticks = true;
std::uint64_t now_us(void*) {
  if (clock_ticks) {
    chip.advance_us(1);
    ++mcu_us;
  }
  return mcu_us;
}

aloft::ImuBus chip_bus() {
  aloft::ImuBus bus = chip.bus();
  bus.now_us = now_us;
  return bus;
}

std::optional<aloft::icm42688p::Icm42688pDriver<float>> driver;
#if !defined(ALOFT_STM32F405_TIMING_BASELINE)
std::optional<aloft_stm32f405::Pipeline> pipeline;
aloft::Status pushed = aloft::Status::ok;

void push(void*, const aloft::ImuSample<float>& sample) {
  const aloft::Status s = pipeline->push(sample);
  if (s != aloft::Status::ok) pushed = s;
}

bool step() {
  aloft::icm42688p::SampleSink<float> sink;
  sink.push = push;
  return driver->poll(sink) == aloft::Status::ok && pushed == aloft::Status::ok;
}
#else
volatile std::uint8_t byte_sink;
std::uint8_t burst[aloft::icm42688p::kPacket3Bytes];

// The driver's bus reads for one packet, without decoding.
bool step() {
  const aloft::ImuBus bus = chip_bus();
  std::uint8_t status_and_count[3];
  if (bus.read(bus.context, aloft::icm42688p::bank0::int_status, status_and_count, 3) != aloft::Status::ok)
    return false;
  if (bus.read(bus.context, aloft::icm42688p::bank0::fifo_data, burst, sizeof burst) != aloft::Status::ok)
    return false;
  byte_sink =
      static_cast<std::uint8_t>(status_and_count[2] + burst[0] + burst[15] + (bus.now_us(bus.context) & 1u));
  return true;
}
#endif

}  // namespace

int main() {
  aloft::port::init();
  aloft::port::ReportWriter out;
  aloft::port::report_calibration(out);
  driver.emplace(chip_bus(), aloft::icm42688p::DriverSettings());
  if (driver->begin() != aloft::Status::ok) {
    out.text("the fake ICM-42688-P did not come up").line();
    return 1;
  }
  clock_ticks = false;
#if !defined(ALOFT_STM32F405_TIMING_BASELINE)
  pipeline.emplace(aloft_stm32f405::flight_inertia(), aloft_stm32f405::pipeline_settings());
#endif
  std::uint64_t start = 0;
  for (unsigned i = 0; i < samples; ++i) {
    if (i == first_timed_sample) start = aloft::port::ticks();
    chip.advance_us(period_us);
    mcu_us += period_us;
#if !defined(ALOFT_STM32F405_TIMING_BASELINE)
    if (i == first_timed_sample && !pipeline->airborne()) {
      out.text("not airborne when the timing starts").line();
      return 1;
    }
#endif
    if (!step()) {
      out.text("sample ").integer(i).text(" not delivered").line();
      return 1;
    }
  }
  const std::uint64_t steady_ticks = aloft::port::ticks() - start;
#if !defined(ALOFT_STM32F405_TIMING_BASELINE)
  if (!pipeline->airborne() || pipeline->stream().samples != samples) {
    out.text("the flight ended inside the timed samples, or samples were lost").line();
    return 1;
  }
#endif
  out.text("steady_updates ").integer(samples - first_timed_sample).line();
  out.text("steady_ticks ").integer(static_cast<std::int64_t>(steady_ticks)).line();
  return 0;
}
