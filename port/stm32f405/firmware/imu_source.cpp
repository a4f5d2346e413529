// The ICM-42688-P driver behind imu_source.hpp; its state is static here, so its RAM shows
// in .bss (no heap).
#include "imu_source.hpp"

#include <optional>

namespace aloft_stm32f405 {

namespace {

using Driver = aloft::icm42688p::Icm42688pDriver<float>;

std::optional<Driver> driver;

}  // namespace

aloft::Status imu_bring_up(const aloft::ImuBus& bus, std::uint8_t& who_am_i) {
  driver.emplace(bus, aloft::icm42688p::DriverSettings());
  const aloft::Status begun = driver->begin();
  who_am_i = who_am_i_expected;
  // After the soft reset bank 0 is selected: WHO_AM_I is read again for the report.
  if (begun == aloft::Status::sensor_not_found) {
    who_am_i = 0;
    const aloft::Status read = bus.read(bus.context, who_am_i_register, &who_am_i, 1);
    if (read != aloft::Status::ok) return read;
  }
  return begun;
}

aloft::Status imu_poll(const aloft::icm42688p::SampleSink<float>& sink) { return driver->poll(sink); }

const aloft::icm42688p::DriverCounters& imu_counters() { return driver->counters(); }

std::uint64_t imu_bus_now_us() {
  const aloft::ImuBus& bus = driver->bus();
  return bus.now_us(bus.context);
}

}  // namespace aloft_stm32f405
