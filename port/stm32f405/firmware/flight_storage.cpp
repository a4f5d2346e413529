#include "flight_storage.hpp"

#include <optional>

#include "aloft/records/flight_record_from_result.hpp"
#include "aloft/records/record_ring.hpp"

namespace aloft_stm32f405 {
namespace {

std::optional<aloft::RecordRing> ring;  // emplaced once the device is known (no heap)
RecordHashes record_hashes;

}  // namespace

aloft::Status start_flight_storage(const aloft::BlockDevice& device, RecordHashes hashes) {
  record_hashes = hashes;
  ring.emplace(device);
  return ring->mount();
}

aloft::Status store_flight(const aloft::FlightResult<float>& flight, std::uint32_t& sequence) {
  if (!ring) return aloft::Status::storage_full;
  aloft::FlightRecord record =
      aloft::make_flight_record(flight, record_hashes.tensor, record_hashes.settings);
  const aloft::Status stored = ring->append(record);
  sequence = record.sequence;
  return stored;
}

}  // namespace aloft_stm32f405
