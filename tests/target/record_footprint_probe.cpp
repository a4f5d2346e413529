// Three images that differ only in what they use, to measure with arm-none-eabi-size
// what the flight records add to a firmware (issue 23: at most 2 KiB of flash and 256 B of
// RAM). They are built, never run (the STM32 flash interface is not on the mps2 board):
//   ALOFT_RECORD_PROBE 0  the port alone
//   ALOFT_RECORD_PROBE 1  + the STM32F405 internal-flash driver, each call used once
//   ALOFT_RECORD_PROBE 2  + the record ring: mount, a record made from a FlightResult,
//                         append, and a walk over the stored records
// Flight-record code = size(2) - size(1); the driver = size(1) - size(0).
#include <cstdint>

#include "aloft/records/flight_record_from_result.hpp"
#include "aloft/records/record_ring.hpp"
#include "aloft_port/port.hpp"
#include "internal_flash.hpp"

#ifndef ALOFT_RECORD_PROBE
#error "define ALOFT_RECORD_PROBE"
#endif

namespace {
volatile std::uint32_t sink;
volatile std::uint32_t source = 3;
}  // namespace

int main() {
  aloft::port::init();
#if ALOFT_RECORD_PROBE >= 1
  static aloft::port::stm32f405::InternalFlash flash;
  const aloft::BlockDevice& device = flash.device();
#endif
#if ALOFT_RECORD_PROBE == 1
  std::uint8_t bytes[4] = {1, 2, 3, 4};
  sink = static_cast<std::uint32_t>(device.read(device.context, 0, source, bytes, 4));
  sink = static_cast<std::uint32_t>(device.program(device.context, 0, source, bytes, 4));
  sink = static_cast<std::uint32_t>(device.erase(device.context, source));
#elif ALOFT_RECORD_PROBE == 2
  static aloft::RecordRing ring(device);
  aloft::FlightResult<float> result;
  result.samples = source;
  result.overall.add_values(0.01f * static_cast<float>(source), 0.02f);
  if (ring.mount() == aloft::Status::ok) {
    aloft::FlightRecord record = aloft::make_flight_record(result, source, source + 1);
    sink = static_cast<std::uint32_t>(ring.append(record));
    sink = static_cast<std::uint32_t>(ring.for_each_record(
        [](const aloft::FlightRecord& r, std::uint32_t, std::uint32_t) { sink = r.sequence; }));
  }
#endif
  return static_cast<int>(sink);
}
