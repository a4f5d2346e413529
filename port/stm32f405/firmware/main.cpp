// The aloft firmware for an STM32F405 flight controller: brings up the board (clocks,
// SysTick, SPI1), finds the ICM-42688-P and runs the onboard pipeline (driver -> release
// -> check -> result) on its samples, one report line per flight.
//
// The sensor's bus is SPI1 (../spi1_imu_bus.hpp), or, in the replay image built with
// ALOFT_STM32F405_FAKE_BUS, a fake chip that plays a recorded throw's FIFO bytes (see
// CMakeLists.txt). Exit status (a test reads it through semihosting):
//   0 the replay's recording ended        3 no ICM-42688-P (WHO_AM_I not 0x47)
//   1 set-up failed                       4 the bus failed
//   5 the sensor stopped delivering samples (the flight image never ends otherwise)
#include <cstdint>
#include <optional>

#include "aloft_port/port.hpp"
#include "aloft_port/report_writer.hpp"
#include "flight_settings.hpp"
#include "imu_source.hpp"

#if defined(ALOFT_STM32F405_FAKE_BUS)
#include "fake_imu_bus.hpp"  // provides fake_imu_bus(): see CMakeLists.txt
#else
#include "spi1_imu_bus.hpp"
#endif

namespace {

using aloft::port::ReportWriter;
using aloft_stm32f405::Pipeline;

#if defined(ALOFT_STM32F405_FAKE_BUS)
constexpr const char* bus_name = "the fake bus";
aloft::ImuBus board_imu_bus() { return aloft_stm32f405::fake_imu_bus(); }
constexpr int exit_stream_ended = 0;
#else
constexpr const char* bus_name = "SPI1";
aloft::ImuBus board_imu_bus() {
  aloft::port::stm32f405::spi1_init();
  return aloft::port::stm32f405::spi1_imu_bus();
}
constexpr int exit_stream_ended = 5;
#endif
constexpr int exit_setup_failed = 1;
constexpr int exit_sensor_not_found = 3;
constexpr int exit_bus_failed = 4;

// The stream has ended when no sample came for this long (MCU clock).
constexpr std::uint64_t stream_end_after_us = 100000;
constexpr std::uint16_t batch_capacity = 16;

// Static storage, so the pipeline's whole memory shows in .bss; emplaced once the tensor
// is validated (no heap).
std::optional<Pipeline> pipeline;
aloft::ImuSample<float> batch[batch_capacity];

// Whole microseconds as seconds with six decimals.
void seconds(ReportWriter& out, std::uint64_t us) {
  out.integer(static_cast<std::int64_t>(us / 1000000u)).text(".");
  char digits[7];
  std::uint32_t fraction = static_cast<std::uint32_t>(us % 1000000u);
  for (int i = 5; i >= 0; --i, fraction /= 10u) digits[i] = static_cast<char>('0' + fraction % 10u);
  digits[6] = '\0';
  out.text(digits);
}

void report_flight(const aloft::FlightResult<float>& flight, std::uint64_t t0_us) {
  const float rad_to_deg = 57.2957795f;
  ReportWriter out;
  out.text("flight ").integer(flight.flight_number).text(": release_s ");
  seconds(out, flight.release_us - t0_us);
  out.text(" landing_s ");
  if (flight.landed) {
    seconds(out, flight.landing_us - t0_us);
  } else {
    out.text("null");
  }
  out.text(" samples ").integer(flight.samples).text(" gaps ").integer(flight.gaps);
  out.text(" rms_da_deg ").fixed(flight.overall.rms_da() * rad_to_deg, 6);
  out.text(" rms_rel_err ").fixed(flight.overall.rms_relative_error(), 6).line();
}

// Runs the pipeline until the stream ends; the exit status.
int run(const aloft::ImuBus& bus) {
  ReportWriter out;
  std::uint64_t t0_us = 0;
  std::uint64_t last_sample_at_us = bus.now_us(bus.context);
  aloft::FlightResult<float> flight;
  while (bus.now_us(bus.context) - last_sample_at_us < stream_end_after_us) {
    std::uint16_t count = 0;
    const aloft::Status polled = aloft_stm32f405::imu_poll(bus, batch, batch_capacity, count);
    if (polled != aloft::Status::ok) {
      out.text("ICM-42688-P on ").text(bus_name).text(": ").text(aloft::describe(polled)).line();
      return exit_bus_failed;
    }
    if (count > 0) last_sample_at_us = bus.now_us(bus.context);
    for (std::uint16_t i = 0; i < count; ++i) {
      if (pipeline->stream().samples == 0) t0_us = batch[i].t_us;
      const aloft::Status pushed = pipeline->push(batch[i]);
      if (pushed != aloft::Status::ok) out.text("sample dropped: ").text(aloft::describe(pushed)).line();
      if (pipeline->take_finished_flight(flight)) report_flight(flight, t0_us);
    }
  }
  pipeline->finish();
  if (pipeline->take_finished_flight(flight)) report_flight(flight, t0_us);
  out.text("stream ended: no sample for ").integer(static_cast<std::int64_t>(stream_end_after_us / 1000u));
  out.text(" ms after ").integer(pipeline->stream().samples).text(" samples").line();
  return exit_stream_ended;
}

}  // namespace

int main() {
  aloft::port::init();
  ReportWriter out;
  const aloft::ImuBus bus = board_imu_bus();
  std::uint8_t who_am_i = 0;
  const aloft::Status found = aloft_stm32f405::imu_bring_up(bus, who_am_i);
  if (found == aloft::Status::sensor_not_found) {
    out.text("ICM-42688-P not found on ").text(bus_name).text(": WHO_AM_I reads ").hex_byte(who_am_i);
    out.text(", expected ").hex_byte(aloft_stm32f405::who_am_i_expected).line();
    return exit_sensor_not_found;
  }
  if (found != aloft::Status::ok) {
    out.text("ICM-42688-P on ").text(bus_name).text(": ").text(aloft::describe(found)).line();
    return exit_bus_failed;
  }
  aloft::InertiaTensor<float> inertia;
  const aloft::Status made = aloft_stm32f405::make_inertia(inertia);
  if (made != aloft::Status::ok) {
    out.text("inertia tensor rejected: ").text(aloft::describe(made)).line();
    return exit_setup_failed;
  }
  pipeline.emplace(inertia, aloft_stm32f405::pipeline_settings());
  out.text("ICM-42688-P found on ").text(bus_name).text("; onboard pipeline running, K = ");
  out.integer(aloft_stm32f405::live_simulations).line();
  return run(bus);
}
