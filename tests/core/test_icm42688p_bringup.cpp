// ICM-42688-P driver bring-up on the fake chip: the configuration the datasheet asks for
// ends up in the registers, and each way bring-up or a later check can fail gives its
// own Status and count.
#include "aloft/sensor/icm42688p_driver.hpp"
#include "fake_icm42688p.hpp"
#include "icm42688p_stream_check.hpp"
#include "test_api.hpp"

namespace {

using aloft::Status;
using aloft::icm42688p::DriverSettings;
using aloft::icm42688p::Icm42688pDriver;
using aloft::icm42688p::OutputDataRate;
using aloft_test::FakeChipFaults;
using aloft_test::FakeIcm42688p;
namespace b0 = aloft::icm42688p::bank0;

DriverSettings settings_at(OutputDataRate odr) {
  DriverSettings s;
  s.odr = odr;
  return s;
}

}  // namespace

ALOFT_TEST_CASE("ICM-42688-P bring-up writes the datasheet's configuration", "[icm42688p]") {
  FakeIcm42688p chip(&aloft_test::mixed_sample);
  Icm42688pDriver<float> driver(chip.bus(), settings_at(OutputDataRate::hz1000));
  ALOFT_REQUIRE(driver.begin() == Status::ok);
  ALOFT_CHECK(chip.reg(0, b0::intf_config0) == 0x30);           // big-endian count and data, count in bytes
  ALOFT_CHECK((chip.reg(0, b0::intf_config1) & 0x07) == 0x01);  // PLL, no RTC
  ALOFT_CHECK(chip.reg(0, b0::fifo_config) == 0x40);            // stream-to-FIFO
  ALOFT_CHECK(chip.reg(0, b0::fifo_config1) == 0x47);           // resume partial read, temp, gyro, accel
  ALOFT_CHECK(chip.reg(0, b0::tmst_config) == 0x21);            // stamps on, 1 µs, absolute, no FSYNC
  ALOFT_CHECK(chip.reg(0, b0::gyro_config0) == 0x06);           // ±2000 °/s, 1 kHz
  ALOFT_CHECK(chip.reg(0, b0::accel_config0) == 0x06);          // ±16 g, 1 kHz
  ALOFT_CHECK(chip.reg(0, b0::pwr_mgmt0) == 0x0F);              // both in low-noise mode
  // AAF at 258 Hz: DELT 6, DELTSQR 36, BITSHIFT 10 (§5.3 table).
  ALOFT_CHECK(chip.reg(1, 0x0B) == 0xA0);  // gyro AAF on (bit 1 clear)
  ALOFT_CHECK(chip.reg(1, 0x0C) == 6);
  ALOFT_CHECK(chip.reg(1, 0x0D) == 36);
  ALOFT_CHECK(chip.reg(1, 0x0E) == 0xA0);
  ALOFT_CHECK(chip.reg(2, 0x03) == 12);
  ALOFT_CHECK(chip.reg(2, 0x04) == 36);
  ALOFT_CHECK(chip.reg(2, 0x05) == 0xA0);
  ALOFT_CHECK(driver.counters().register_faults == 0u);
}

ALOFT_TEST_CASE("ICM-42688-P bring-up at 4 kHz sets the rate and the 997 Hz filter", "[icm42688p]") {
  FakeIcm42688p chip(&aloft_test::mixed_sample);
  Icm42688pDriver<float> driver(chip.bus(), settings_at(OutputDataRate::hz4000));
  ALOFT_REQUIRE(driver.begin() == Status::ok);
  ALOFT_CHECK(chip.reg(0, b0::gyro_config0) == 0x04);
  ALOFT_CHECK(chip.reg(0, b0::accel_config0) == 0x04);
  ALOFT_CHECK(chip.reg(1, 0x0C) == 21);
  ALOFT_CHECK(chip.reg(1, 0x0D) == (440 & 0xFF));
  ALOFT_CHECK(chip.reg(1, 0x0E) == ((6 << 4) | (440 >> 8)));
  ALOFT_CHECK(chip.reg(2, 0x03) == 42);
  ALOFT_CHECK(chip.period_us() == 250u);
}

ALOFT_TEST_CASE("ICM-42688-P absent or another chip: sensor_not_found", "[icm42688p]") {
  // 0x00: what QEMU's SPI without a sensor reads; 0x44: the ICM-42686-P.
  for (std::uint8_t who : {std::uint8_t{0x00}, std::uint8_t{0x44}, std::uint8_t{0xFF}}) {
    FakeChipFaults faults;
    faults.who_am_i = who;
    FakeIcm42688p chip(&aloft_test::mixed_sample, faults);
    Icm42688pDriver<float> driver(chip.bus(), DriverSettings());
    ALOFT_CHECK(driver.begin() == Status::sensor_not_found);
    ALOFT_CHECK(chip.reg(0, b0::pwr_mgmt0) == 0x00);  // nothing configured
  }
}

ALOFT_TEST_CASE("ICM-42688-P register that does not stick: register_not_kept", "[icm42688p]") {
  FakeChipFaults faults;
  faults.stuck_bank = 1;
  faults.stuck_reg = 0x0C;  // GYRO_CONFIG_STATIC3: the AAF keeps its reset DELT 13
  FakeIcm42688p chip(&aloft_test::mixed_sample, faults);
  Icm42688pDriver<double> driver(chip.bus(), DriverSettings());
  ALOFT_CHECK(driver.begin() == Status::register_not_kept);
  ALOFT_CHECK(driver.counters().register_faults == 1u);
}

ALOFT_TEST_CASE("ICM-42688-P register changed while running is found, rewritten and counted", "[icm42688p]") {
  FakeIcm42688p chip(&aloft_test::mixed_sample);
  DriverSettings settings;
  settings.register_check_every = 4;
  Icm42688pDriver<float> driver(chip.bus(), settings);
  ALOFT_REQUIRE(driver.begin() == Status::ok);
  aloft_test::StreamCheck<float> check;
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 200, 1000) == 0u);
  // A glitch switches the gyro to 2 kHz: within one walk of the table (18 registers,
  // one every 4 polls) the driver finds it, rewrites it and says so once.
  chip.corrupt_register(0, b0::gyro_config0, 0x05);
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 18 * 4, 1000) == 1u);
  ALOFT_CHECK(driver.counters().register_faults == 1u);
  ALOFT_CHECK(chip.reg(0, b0::gyro_config0) == 0x06);
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 200, 1000) == 0u);
  ALOFT_CHECK(driver.counters().register_faults == 1u);
}
