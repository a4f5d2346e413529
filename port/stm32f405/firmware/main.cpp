// The aloft firmware for an STM32F405 flight controller: brings up the board (clocks,
// SysTick, SPI1), finds the ICM-42688-P and runs the onboard pipeline (driver -> release
// -> check -> result) on its samples, one report line per flight.
//
// The sensor's bus is SPI1 (../spi1_imu_bus.hpp), or, in the replay image built with
// ALOFT_STM32F405_FAKE_BUS, a fake chip that plays a recorded throw's FIFO bytes (see
// CMakeLists.txt). Each flight's record is stored (flight_storage.hpp) in the internal
// flash, or in the replay image on a RAM fake that is written out at the end. Exit status (a test reads it
// through semihosting):
//   0 the replay's recording ended        3 no ICM-42688-P (WHO_AM_I not 0x47)
//   4 the bus failed                      5 the sensor stopped delivering samples (the
//                                           flight image never ends otherwise)
// (A tensor the pipeline cannot take stops the build, not the image: flight_settings.hpp.)
#include <cstdint>
#include <optional>

#include "aloft/cold_path.hpp"
#include "aloft_port/port.hpp"
#include "aloft_port/report_writer.hpp"
#include "flight_lines.hpp"
#include "flight_settings.hpp"
#include "imu_source.hpp"

#if defined(ALOFT_STM32F405_FAKE_BUS)
#include "fake_flash.hpp"
#include "fake_imu_bus.hpp"  // provides fake_imu_bus(): see CMakeLists.txt
#include "record_area_dump.hpp"
#include "replay_throw.hpp"
#include "aloft/records/flight_record_from_result.hpp"
#include "aloft/records/settings_hash.hpp"
#else
#include "internal_flash.hpp"
#include "spi1_imu_bus.hpp"
#endif
#if !defined(ALOFT_STM32F405_NO_RECORDS)
#include "flight_storage.hpp"
#endif

namespace {

using aloft::port::ReportWriter;
using aloft_stm32f405::Pipeline;

// A message that ends in a status's phrase: `what`, the phrase, the line's end. Out of line:
// one copy of the phrase's lookup (aloft::describe) for every such message.
ALOFT_COLD void say_status(const char* what, aloft::Status status) {
  ReportWriter().text(what).text(aloft::describe(status)).line();
}

#if defined(ALOFT_STM32F405_FAKE_BUS)
// The bus's name as a literal, joined to its messages' text when the image is compiled.
#define ALOFT_STM32F405_BUS_NAME "the fake bus"
aloft::ImuBus board_imu_bus() { return aloft_stm32f405::fake_imu_bus(); }
constexpr int exit_stream_ended = 0;

// QEMU does not model the flash controller, so the replay image keeps its record ring on
// the RAM fake (port/fakes/fake_flash.hpp, three 512-byte blocks) and writes the record
// area out by semihosting at the end (ALOFT_STM32F405_RECORDS_PATH, given by the test);
// the host reads it back with `aloft records`' reader.
aloft::testing::FakeFlash<512, 3> record_flash;
const aloft::BlockDevice& record_device() { return record_flash.device(); }

void write_records() {
  say_status("record area written: ",
             aloft::port::write_record_area(record_flash.device(), ALOFT_STM32F405_RECORDS_PATH));
}

aloft::OnboardPipelineSettings<float> pipeline_settings() {
  namespace t = aloft_stm32f405;
  aloft::OnboardPipelineSettings<float> settings;
  const float* q = t::replay_sensor_to_body_wxyz;
  settings.check.sensor_to_body = aloft::Quat<float>(q[0], q[1], q[2], q[3]);
  settings.imu_position_known = t::replay_imu_position_known;
  const float* r = t::replay_imu_position_m;
  settings.imu_position_m = aloft::Vec3<float>(r[0], r[1], r[2]);
  return settings;
}

// The replay checks the recorded throw with the body it was thrown with, as the host's
// `aloft replay --body` does (replay_throw.hpp: the tensor for the records, and its
// decomposition as the host made it).
aloft::InertiaTensor<float> flight_inertia() {
  return aloft::InertiaTensor<float>::from_accepted_parts(aloft_stm32f405::replay_inertia_parts);
}
aloft::Mat3<float> body_tensor() {
  aloft::Mat3<float> tensor;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) tensor(r, c) = aloft_stm32f405::replay_inertia_kg_m2[r][c];
  }
  return tensor;
}
#if !defined(ALOFT_STM32F405_NO_RECORDS)
// The replay's body and settings are the recorded throw's: hashed here, at start-up, by the
// code the flight image's build runs (bake_flight_inertia), so the records test covers it.
aloft_stm32f405::RecordHashes record_hashes() {
  return {aloft::tensor_hash(body_tensor()),
          aloft::settings_hash(pipeline_settings(), aloft_stm32f405::live_simulations)};
}
#endif
#else
#define ALOFT_STM32F405_BUS_NAME "SPI1"
aloft::ImuBus board_imu_bus() {
  aloft::port::stm32f405::spi1_init();
  return aloft::port::stm32f405::spi1_imu_bus();
}
constexpr int exit_stream_ended = 5;

#if !defined(ALOFT_STM32F405_NO_RECORDS)
// The records go to the last three 128 KiB sectors of the internal flash (9 to 11).
aloft::port::stm32f405::InternalFlash record_flash;
const aloft::BlockDevice& record_device() { return record_flash.device(); }
#endif
void write_records() {}
using aloft_stm32f405::flight_inertia;
using aloft_stm32f405::pipeline_settings;
#if !defined(ALOFT_STM32F405_NO_RECORDS)
// Hashed on the build machine (bake_flight_inertia): the image carries no settings hasher.
aloft_stm32f405::RecordHashes record_hashes() {
  return {aloft_stm32f405::flight_tensor_hash, aloft_stm32f405::flight_settings_hash};
}
#endif
#endif

#if defined(ALOFT_STM32F405_NO_RECORDS)
// The image without flight records, built only to measure what the records add to
// footprint.json (CMakeLists.txt).
void start_records() {}
void store_record(const aloft::FlightResult<float>&) {}
#else
void start_records() {
  const aloft::Status mounted = aloft_stm32f405::start_flight_storage(record_device(), record_hashes());
  if (mounted != aloft::Status::ok) say_status("flight records off: ", mounted);
}

// Stores the flight's record and says which sequence number it got.
void store_record(const aloft::FlightResult<float>& f) {
  std::uint32_t sequence = 0;
  const aloft::Status stored = aloft_stm32f405::store_flight(f, sequence);
  if (stored != aloft::Status::ok) {
    say_status("record not stored: ", stored);
    return;
  }
  ReportWriter out;
  aloft_flight_lines::write_integer_line(out, "record_sequence ", sequence);
}
#endif

constexpr int exit_sensor_not_found = 3;
constexpr int exit_bus_failed = 4;

// The stream has ended when no sample came for this long (MCU clock).
constexpr std::uint64_t stream_end_after_us = 100000;

// Static storage, so the pipeline's whole memory shows in .bss; emplaced once the tensor
// is validated (no heap).
std::optional<Pipeline> pipeline;
std::uint32_t samples_this_poll = 0;

// Each finished flight, in the lines the host's replay prints too (flight_lines.hpp);
// times in the driver's base: µs after the first sample. The flight is read where the
// pipeline holds it, not copied; taken after each burst of samples, not under it: the
// flight's tensor estimate is solved here, and its frames would add to the driver's.
ALOFT_COLD void report_finished_flights() {
  ReportWriter out;
  if (const aloft::FlightResult<float>* flight = pipeline->finished_flight()) {
    aloft_flight_lines::write_flight_lines(out, *flight, 0);
    store_record(*flight);
    pipeline->release_finished_flight();
  }
}

// The driver's sink: each sample into the pipeline as it is decoded.
void push_sample(void*, const aloft::ImuSample<float>& sample) {
  ++samples_this_poll;
  const aloft::Status pushed = pipeline->push(sample);
  if (pushed != aloft::Status::ok) say_status("sample dropped: ", pushed);
}

// The driver's sink: in flash, not on the stack under every sample's path.
constexpr aloft::icm42688p::SampleSink<float> sample_sink{nullptr, push_sample};

// Runs the pipeline until the stream ends; the exit status. The bus is the driver's own
// copy (imu_bus_now_us), so main's frame, under every sample's path, holds none.
int run() {
  ReportWriter out;
  std::uint64_t last_sample_at_us = aloft_stm32f405::imu_bus_now_us();
  while (aloft_stm32f405::imu_bus_now_us() - last_sample_at_us < stream_end_after_us) {
    samples_this_poll = 0;
    const aloft::Status polled = aloft_stm32f405::imu_poll(sample_sink);
    if (polled == aloft::Status::register_not_kept) {
      out.text("ICM-42688-P on " ALOFT_STM32F405_BUS_NAME ": a register lost its setting; rewritten\n");
    } else if (polled != aloft::Status::ok) {
      say_status("ICM-42688-P on " ALOFT_STM32F405_BUS_NAME ": ", polled);
      return exit_bus_failed;
    }
    if (samples_this_poll > 0) last_sample_at_us = aloft_stm32f405::imu_bus_now_us();
    report_finished_flights();
  }
  pipeline->finish();
  report_finished_flights();
  aloft_flight_lines::write_integer_line(out, "stream_samples ", pipeline->stream().samples);
  aloft_flight_lines::write_integer_line(out, "stream_gaps ", pipeline->stream().gaps);
  write_records();
  out.text("stream ended: idle ").integer(static_cast<std::int64_t>(stream_end_after_us / 1000u));
  out.text(" ms after ").integer(pipeline->stream().samples).text(" samples").line();
  return exit_stream_ended;
}

// The pipeline, its tensor and settings made in place (OnboardPipeline's constructor from
// makers): neither is built on this frame and copied. The tensor was checked and decomposed
// when the image was built (flight_settings.hpp).
ALOFT_COLD void start_pipeline() {
  pipeline.emplace([] { return flight_inertia(); }, [] { return pipeline_settings(); });
}

// Set-up: the board's bus, the sensor, the pipeline and the records; 0, or the exit status.
// Out of line, so that its locals (the bus among them: the driver keeps its own copy) are
// off the stack before the per-sample path runs, and the deepest path is the flight's, not
// this one stacked on it (footprint.json's stack_bytes).
ALOFT_COLD int set_up() {
  ReportWriter out;
  const aloft::ImuBus bus = board_imu_bus();
  std::uint8_t who_am_i = 0;
  const aloft::Status found = aloft_stm32f405::imu_bring_up(bus, who_am_i);
  if (found == aloft::Status::sensor_not_found) {
    out.text("ICM-42688-P not found on " ALOFT_STM32F405_BUS_NAME ": WHO_AM_I reads ").hex_byte(who_am_i);
    out.text(", expected ").hex_byte(aloft_stm32f405::who_am_i_expected).line();
    return exit_sensor_not_found;
  }
  if (found != aloft::Status::ok) {
    say_status("ICM-42688-P on " ALOFT_STM32F405_BUS_NAME ": ", found);
    return exit_bus_failed;
  }
  start_pipeline();
  start_records();
  out.text("ICM-42688-P found on " ALOFT_STM32F405_BUS_NAME "; onboard pipeline running, K = ");
  out.integer(aloft_stm32f405::live_simulations).line();
  return 0;
}

}  // namespace

// Set-up, then the samples (the per-sample work is in push_sample).
ALOFT_COLD int main() {
  aloft::port::init();
  const int set_up_status = set_up();
  if (set_up_status != 0) return set_up_status;
  return run();
}
