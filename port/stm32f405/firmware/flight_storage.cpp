#include "flight_storage.hpp"

#include <optional>

#include "aloft/records/flight_record_from_result.hpp"
#include "aloft/records/record_ring.hpp"
#include "flight_settings.hpp"

namespace aloft_stm32f405 {
namespace {

std::optional<aloft::RecordRing> ring;  // emplaced once the device is known (no heap)
std::uint32_t tensor_hash_value = 0;
std::uint32_t settings_hash_value = 0;

}  // namespace

aloft::Status start_flight_storage(const aloft::BlockDevice& device, const aloft::Mat3<float>& tensor,
                                   const aloft::OnboardPipelineSettings<float>& settings) {
  tensor_hash_value = aloft::tensor_hash(tensor);
  settings_hash_value = aloft::settings_hash(settings, live_simulations);
  ring.emplace(device);
  return ring->mount();
}

aloft::Status store_flight(const aloft::FlightResult<float>& flight, std::uint32_t& sequence) {
  if (!ring) return aloft::Status::storage_full;
  aloft::FlightRecord record = aloft::make_flight_record(flight, tensor_hash_value, settings_hash_value);
  const aloft::Status stored = ring->append(record);
  sequence = record.sequence;
  return stored;
}

}  // namespace aloft_stm32f405
