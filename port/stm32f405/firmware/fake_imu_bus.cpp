// fake_imu_bus() of fake_imu_bus.hpp: the tests' fake ICM-42688-P
// (port/fakes/fake_icm42688p.hpp) playing the recorded throw of replay_throw.hpp from
// flash: sample k is the throw's k-th, and after its last one the chip delivers packets
// without data (-32768, dropped by the driver), so the firmware sees its stream end.
//
// The chip's simulated MCU clock moves by kMicrosecondsPerClockRead at each now_us call,
// not by 1 µs, so that the firmware's polls reach the chip's 1 kHz samples in a few
// thousand bus calls under QEMU; a poll reads the clock a few times, so the FIFO never
// fills (128 packets) and the stream has no gap, as in the FIFO file.
#include "fake_imu_bus.hpp"

#include "fake_icm42688p.hpp"
#include "replay_throw.hpp"

namespace aloft_stm32f405 {

namespace {

constexpr std::uint64_t kMicrosecondsPerClockRead = 50;

aloft_test::ChipSample recorded(std::uint32_t k) {
  return k < replay_chip_sample_count ? replay_chip_samples[k] : aloft_test::no_data_sample();
}

aloft_test::FakeIcm42688p chip(recorded);

std::uint64_t now_us(void* context) {
  auto* c = static_cast<aloft_test::FakeIcm42688p*>(context);
  c->advance_us(kMicrosecondsPerClockRead - 1);
  return chip.bus().now_us(context);  // the chip's own read adds the last microsecond
}

}  // namespace

aloft::ImuBus fake_imu_bus() {
  aloft::ImuBus bus = chip.bus();
  bus.now_us = now_us;
  return bus;
}

}  // namespace aloft_stm32f405
