// The firmware's flight records: one per finished flight, appended to a record ring
// (aloft/records/record_ring.hpp) on the block device the image gives it — the STM32F405's
// internal flash on a board (../internal_flash.hpp), the RAM fake under QEMU, which does
// not model the flash interface. Each record carries the hashes of the tensor and the
// settings it was checked with (aloft/records/flight_record_from_result.hpp).
#pragma once

#include <cstdint>

#include "aloft/records/block_device.hpp"
#include "aloft/onboard/onboard_pipeline.hpp"

namespace aloft_stm32f405 {

// The hashes each record carries: of the tensor and of the settings the flights are
// checked with (aloft/records/flight_record_from_result.hpp, settings_hash.hpp).
struct RecordHashes {
  std::uint32_t tensor = 0;
  std::uint32_t settings = 0;
};

// Mounts the ring on `device` (which must outlive it) and remembers the hashes; ok, or
// the ring's status (the flights are then checked and printed, but not stored).
aloft::Status start_flight_storage(const aloft::BlockDevice& device, RecordHashes hashes);

// Appends the flight's record; its sequence number in `sequence`.
aloft::Status store_flight(const aloft::FlightResult<float>& flight, std::uint32_t& sequence);

}  // namespace aloft_stm32f405
