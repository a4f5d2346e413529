// The stand-in for the ICM-42688-P driver: imu_source.hpp (TODO there).
#include "imu_source.hpp"

namespace aloft_stm32f405 {

aloft::Status imu_bring_up(const aloft::ImuBus& bus, std::uint8_t& who_am_i) {
  who_am_i = 0;
  const aloft::Status read = bus.read(bus.context, who_am_i_register, &who_am_i, 1);
  if (read != aloft::Status::ok) return read;
  return who_am_i == who_am_i_expected ? aloft::Status::ok : aloft::Status::sensor_not_found;
}

aloft::Status imu_poll(const aloft::ImuBus&, aloft::ImuSample<float>*, std::uint16_t, std::uint16_t& count) {
  count = 0;
  return aloft::Status::ok;
}

}  // namespace aloft_stm32f405
