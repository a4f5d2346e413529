// Flight records on a firmware that runs under QEMU or a debugger: store a finished
// flight in the record ring, and write the whole record area out to a host file by
// semihosting, for `aloft records` to read (the end-to-end test of issue 23). On QEMU the
// block device is the RAM fake (port/fakes/fake_flash.hpp: no cut scheduled, it is a
// plain NOR flash in RAM), since QEMU does not model the STM32 flash interface.
#pragma once

#include <cstdint>

#include "aloft/records/flight_record_from_result.hpp"
#include "aloft/records/record_ring.hpp"
#include "semihosting.hpp"

namespace aloft::port {

// Appends the record of `result` (its sequence number is the ring's next one).
template <typename Scalar>
Status store_flight(RecordRing& ring, const FlightResult<Scalar>& result, std::uint32_t tensor_hash_value,
                    std::uint32_t settings_hash_value) {
  FlightRecord record = make_flight_record(result, tensor_hash_value, settings_hash_value);
  return ring.append(record);
}

// Writes every block of `device`, in order, to the host file `path` (created or
// truncated: semihosting mode "wb"), 128 bytes at a time through a stack buffer.
inline Status write_record_area(const BlockDevice& device, const char* path) {
  std::uint32_t length = 0;
  while (path[length] != '\0') ++length;
  const std::uint32_t open_args[3] = {reinterpret_cast<std::uint32_t>(path), 5u /* "wb" */, length};
  const std::uint32_t handle = semihosting::call(semihosting::Operation::open, open_args);
  if (handle == 0xFFFFFFFFu) return Status::bus_error;
  Status result = Status::ok;
  std::uint8_t chunk[flight_record_size];
  for (std::uint32_t b = 0; b < device.block_count && result == Status::ok; ++b) {
    for (std::uint32_t at = 0; at < device.block_size && result == Status::ok; at += sizeof(chunk)) {
      result = device.read(device.context, b, at, chunk, sizeof(chunk));
      const std::uint32_t write_args[3] = {handle, reinterpret_cast<std::uint32_t>(chunk), sizeof(chunk)};
      if (result == Status::ok && semihosting::call(semihosting::Operation::write, write_args) != 0)
        result = Status::bus_error;
    }
  }
  const std::uint32_t close_args[1] = {handle};
  if (semihosting::call(semihosting::Operation::close, close_args) != 0 && result == Status::ok)
    result = Status::bus_error;
  return result;
}

}  // namespace aloft::port
