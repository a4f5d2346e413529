// The ICM-42688-P driver streaming from the fake chip: every sample bit-exact against
// the stream that made the packets, and each fault of the fake's schedule counted,
// recovered from, and its gap reported with the right length.
#include "aloft/sensor/icm42688p_driver.hpp"
#include "fake_icm42688p.hpp"
#include "icm42688p_stream_check.hpp"
#include "test_api.hpp"

namespace {

using aloft::Status;
using aloft::icm42688p::DriverSettings;
using aloft::icm42688p::Icm42688pDriver;
using aloft::icm42688p::OutputDataRate;
using aloft::icm42688p::TimestampClock;
using aloft_test::FakeChipFaults;
using aloft_test::FakeIcm42688p;
using aloft_test::StreamCheck;

DriverSettings settings_at(OutputDataRate odr) {
  DriverSettings s;
  s.odr = odr;
  return s;
}

// The stream, polled every interval until the chip has made `packets`; then drained.
template <typename S>
void stream(Icm42688pDriver<S>& driver, FakeIcm42688p& chip, StreamCheck<S>& check, std::uint32_t packets,
            std::uint32_t interval_us) {
  while (chip.packets_made() < packets) {
    chip.advance_us(interval_us);
    ALOFT_REQUIRE(driver.poll(check.sink()) == Status::ok);
  }
  for (int i = 0; i < 4; ++i) ALOFT_REQUIRE(driver.poll(check.sink()) == Status::ok);
}

// ≥ 100,000 packets at each rate, with power-up packets without data first.
template <typename S>
void check_bit_exact(OutputDataRate odr, std::uint32_t interval_us) {
  FakeChipFaults faults;
  faults.packets_without_data = 30;
  FakeIcm42688p chip(&aloft_test::mixed_sample, faults);
  Icm42688pDriver<S> driver(chip.bus(), settings_at(odr));
  ALOFT_REQUIRE(driver.begin() == Status::ok);
  StreamCheck<S> check;
  check.first_index = 30;
  check.period_us = chip.period_us();
  stream(driver, chip, check, 100000, interval_us);
  const auto& c = driver.counters();
  ALOFT_CHECK(c.packets == chip.packets_made() - chip.fifo_bytes() / 16u);
  ALOFT_CHECK(c.packets >= 100000u - 16u);
  ALOFT_CHECK(c.invalid == 30u);
  ALOFT_CHECK(c.samples == c.packets - 30u);
  ALOFT_CHECK(check.samples == c.samples);
  ALOFT_CHECK(check.mismatches == 0u);
  ALOFT_CHECK(check.gaps == 0u);
  ALOFT_CHECK(check.clipped > 0u);  // the stream holds full-scale counts, flagged
  ALOFT_CHECK(c.overflows + c.resyncs + c.register_faults + c.bus_errors + c.gaps == 0u);
}

}  // namespace

ALOFT_TEST_CASE("ICM-42688-P stream: 100,000 packets decode bit-exact at 1, 2 and 4 kHz", "[icm42688p]") {
  check_bit_exact<float>(OutputDataRate::hz1000, 1000);
  check_bit_exact<double>(OutputDataRate::hz2000, 7000);  // 14 packets a poll
  check_bit_exact<float>(OutputDataRate::hz4000, 1000);
}

ALOFT_TEST_CASE("ICM-42688-P empty reads are counted and lose nothing", "[icm42688p]") {
  FakeIcm42688p chip(&aloft_test::mixed_sample);
  Icm42688pDriver<float> driver(chip.bus(), DriverSettings());
  ALOFT_REQUIRE(driver.begin() == Status::ok);
  StreamCheck<float> check;
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 100, 1000) == 0u);
  const std::uint32_t before = driver.counters().empty_reads;
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 3, 0) == 0u);  // nothing new: 3 empty
  chip.force_empty_reads(5);                                            // FIFO_COUNT reads 0
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 5, 1000) == 0u);
  ALOFT_CHECK(driver.counters().empty_reads == before + 8u);
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 100, 1000) == 0u);
  ALOFT_CHECK(check.gaps == 0u);
  ALOFT_CHECK(check.mismatches == 0u);
  ALOFT_CHECK(check.samples + 1u >= 200u);
}

ALOFT_TEST_CASE("ICM-42688-P bursts that read 0x80 (FIFO empty) are empty reads and lose nothing",
                "[icm42688p]") {
  FakeIcm42688p chip(&aloft_test::mixed_sample);
  Icm42688pDriver<float> driver(chip.bus(), DriverSettings());
  ALOFT_REQUIRE(driver.begin() == Status::ok);
  StreamCheck<float> check;
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 100, 1000) == 0u);
  const std::uint32_t before = driver.counters().empty_reads;
  chip.empty_bursts(3);  // 1, then 2, then 3 packets waiting: 6 slots of 0x80
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 3, 1000) == 0u);
  ALOFT_CHECK(chip.empty_reads_sent() == 6u);
  ALOFT_CHECK(driver.counters().empty_reads == before + 6u);
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 100, 1000) == 0u);
  const auto& c = driver.counters();
  ALOFT_CHECK(c.resyncs + c.bytes_skipped + c.overflows + c.gaps == 0u);
  ALOFT_CHECK(check.gaps == 0u);
  ALOFT_CHECK(check.mismatches == 0u);
  ALOFT_CHECK(check.samples == chip.packets_made() - chip.fifo_bytes() / 16u);
}

ALOFT_TEST_CASE("ICM-42688-P a 0x80 byte before a burst: counted; the tail it cut is resynchronised",
                "[icm42688p]") {
  FakeIcm42688p chip(&aloft_test::mixed_sample);
  Icm42688pDriver<float> driver(chip.bus(), DriverSettings());
  ALOFT_REQUIRE(driver.begin() == Status::ok);
  StreamCheck<float> check;
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 100, 1000) == 0u);
  const std::uint32_t before = driver.counters().empty_reads;
  chip.advance_us(3000);  // 4 packets wait
  chip.empty_byte_before_next_burst();
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 100, 1000) == 0u);
  const auto& c = driver.counters();
  ALOFT_CHECK(c.empty_reads == before + 1u);
  ALOFT_CHECK(c.resyncs == 1u);
  ALOFT_CHECK(c.bytes_skipped == 15u);  // the cut packet: 15 of its bytes were read
  ALOFT_CHECK(c.overflows + c.bus_errors == 0u);
  ALOFT_REQUIRE(check.gaps == 1u);
  ALOFT_CHECK(check.mismatches == 0u);
  ALOFT_CHECK(c.gaps == 1u);
}

ALOFT_TEST_CASE("ICM-42688-P overflow shorter than a stamp wrap: flushed, gap measured", "[icm42688p]") {
  FakeIcm42688p chip(&aloft_test::mixed_sample);
  Icm42688pDriver<float> driver(chip.bus(), settings_at(OutputDataRate::hz4000));
  ALOFT_REQUIRE(driver.begin() == Status::ok);
  StreamCheck<float> check;
  check.period_us = 250;
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 200, 1000) == 0u);
  // 50 ms without a poll: the 128-packet FIFO holds 32 ms at 4 kHz.
  chip.advance_us(50000);
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 200, 1000) == 0u);
  ALOFT_CHECK(driver.counters().overflows == 1u);
  ALOFT_CHECK(chip.flushes() >= 2u);  // bring-up and the overflow
  ALOFT_REQUIRE(check.gaps == 1u);
  ALOFT_CHECK(check.mismatches == 0u);  // the samples after the gap sit where their stamps say
  // Everything from the last sample read to the first after the flush is missing: the
  // gap spans at least the 50 ms pause.
  ALOFT_CHECK(check.gap_log[0].length_us >= 50000u);
  ALOFT_CHECK(check.gap_log[0].length_us < 65536u);
  ALOFT_CHECK(driver.counters().gaps == 1u);
  ALOFT_CHECK(driver.counters().last_gap_us == check.gap_log[0].length_us);
}

ALOFT_TEST_CASE("ICM-42688-P overflow longer than a stamp wrap: the MCU clock counts the wraps",
                "[icm42688p]") {
  FakeIcm42688p chip(&aloft_test::mixed_sample);
  Icm42688pDriver<double> driver(chip.bus(), DriverSettings());
  ALOFT_REQUIRE(driver.begin() == Status::ok);
  StreamCheck<double> check;
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 300, 1000) == 0u);
  chip.advance_us(300000);  // 300 ms: four and a half wraps of the 16-bit stamp
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 300, 1000) == 0u);
  ALOFT_CHECK(driver.counters().overflows == 1u);
  ALOFT_REQUIRE(check.gaps == 1u);
  ALOFT_CHECK(check.mismatches == 0u);
  ALOFT_CHECK(check.gap_log[0].length_us >= 300000u);
  ALOFT_CHECK(check.gap_log[0].length_us <= 302000u);
}

ALOFT_TEST_CASE("ICM-42688-P garbled header: flush, resync, skipped bytes counted", "[icm42688p]") {
  FakeChipFaults faults;
  faults.garbled_header_packet = 5000;
  FakeIcm42688p chip(&aloft_test::mixed_sample, faults);
  Icm42688pDriver<float> driver(chip.bus(), settings_at(OutputDataRate::hz4000));
  ALOFT_REQUIRE(driver.begin() == Status::ok);
  StreamCheck<float> check;
  check.period_us = 250;
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 2000, 1000) == 0u);
  const auto& c = driver.counters();
  ALOFT_CHECK(c.resyncs == 1u);
  ALOFT_CHECK(c.bytes_skipped == 16u);  // 4 packets a poll at 4 kHz, and 5000 closes its burst
  ALOFT_CHECK(c.empty_reads == 0u);
  ALOFT_REQUIRE(check.gaps == 1u);
  ALOFT_CHECK(check.mismatches == 0u);
  // Sample 4999 was the last before the garbled packet; 5000 and what the flush took are gone.
  ALOFT_CHECK(check.gap_log[0].at_us - check.gap_log[0].length_us == 4999u * 250u);
  ALOFT_CHECK(check.samples > 7000u);
}

ALOFT_TEST_CASE("ICM-42688-P truncated burst: bus error, flush, resync, gap measured", "[icm42688p]") {
  FakeIcm42688p chip(&aloft_test::mixed_sample);
  Icm42688pDriver<float> driver(chip.bus(), settings_at(OutputDataRate::hz4000));
  ALOFT_REQUIRE(driver.begin() == Status::ok);
  StreamCheck<float> check;
  check.period_us = 250;
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 100, 1000) == 0u);
  chip.truncate_next_burst(20);  // the transfer stops 4 bytes into the second packet
  ALOFT_CHECK(aloft_test::run_polls(driver, chip, check, 100, 1000) == 1u);
  const auto& c = driver.counters();
  ALOFT_CHECK(c.bus_errors == 1u);
  ALOFT_CHECK(c.resyncs == 1u);
  ALOFT_REQUIRE(check.gaps == 1u);
  ALOFT_CHECK(check.mismatches == 0u);
  ALOFT_CHECK(check.gap_log[0].length_us > 250u);
}

ALOFT_TEST_CASE("ICM-42688-P on the internal RC clock: stamps scaled by 32/30 to microseconds",
                "[icm42688p]") {
  FakeIcm42688p chip(&aloft_test::mixed_sample);
  DriverSettings settings;
  settings.clock = TimestampClock::internal_rc;
  Icm42688pDriver<float> driver(chip.bus(), settings);
  ALOFT_REQUIRE(driver.begin() == Status::ok);
  ALOFT_CHECK((chip.reg(0, aloft::icm42688p::bank0::intf_config1) & 0x03) == 0x00);
  struct Times {
    std::uint32_t n = 0;
    std::uint64_t worst_error_us = 0;
    static void push(void* c, const aloft::ImuSample<float>& s) {
      auto* t = static_cast<Times*>(c);
      const std::uint64_t nominal = 1000u * t->n++;
      const std::uint64_t e = s.t_us > nominal ? s.t_us - nominal : nominal - s.t_us;
      if (e > t->worst_error_us) t->worst_error_us = e;
    }
  } times;
  for (int i = 0; i < 5000; ++i) {
    chip.advance_us(1000);
    ALOFT_REQUIRE(driver.poll({&times, &Times::push}) == Status::ok);
  }
  ALOFT_CHECK(times.n >= 4990u);
  // Whole ticks of 32/30 µs, rounded down twice: within 2 µs of the chip's own time.
  ALOFT_CHECK(times.worst_error_us <= 2u);
}
