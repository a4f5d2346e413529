// The `replay --fifo` file reader: FIFO bytes encoded from the datasheet become the
// samples that made them, bit for bit, through the firmware's decoder; holes come out as
// gaps of the right length; bad bytes get one line naming the file and the byte offset.
#include <catch2/catch.hpp>

#include <cstdio>

#include "aloft/icm42688p_driver.hpp"
#include "fake_icm42688p.hpp"
#include "fifo_file_writer.hpp"
#include "one_line_error.hpp"
#include "replay/fifo_recording.hpp"
#include "scratch_files.hpp"

namespace {

using aloft::host::read_fifo_recording;
using aloft_test::FifoFile;

// Sample k's values, as the decoder must give them.
void check_holds_sample(const aloft::ImuSample<float>& s, std::uint32_t k) {
  const aloft_test::ChipSample want = aloft_test::mixed_sample(k);
  for (int axis = 0; axis < 3; ++axis) {
    CHECK(s.accel_m_s2[axis] == Approx(want.accel[axis] * 9.80665 / 2048.0).epsilon(1e-6));
    CHECK(s.gyro_rad_s[axis] ==
          Approx(want.gyro[axis] / 16.4 * 3.14159265358979323846 / 180.0).epsilon(1e-6));
    // Bit for bit the firmware's conversion of the raw count.
    CHECK(s.accel_m_s2[axis] ==
          static_cast<float>(want.accel[axis]) * aloft::icm42688p::accel_m_s2_per_lsb<float>());
  }
}

}  // namespace

TEST_CASE("replay --fifo: every packet decodes to the sample that made it", "[replay_fifo]") {
  aloft::test::ScratchDir dir;
  FifoFile file;
  file.packets = 120000;  // ≥ 100,000 packets, with 16-bit stamps wrapping every 65.5 ms
  file.without_data = 25;
  const std::string path = dir.write("throw.bin", file.bytes());
  const aloft::host::Recording r = read_fifo_recording(path, 1000);
  CHECK(r.format == "icm42688p_fifo");
  CHECK(r.path == path);
  CHECK(r.invalid_samples == 25u);
  CHECK(r.bytes_skipped == 0u);
  CHECK(r.t0_us == 0u);
  REQUIRE(r.samples.size() == 120000u - 25u);
  std::uint32_t clipped = 0;
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    const auto& s = r.samples[i];
    REQUIRE(s.t_us == 1000u * i);  // the first valid packet at t = 0
    REQUIRE_FALSE(s.gap_before());
    if (s.clipped()) ++clipped;
  }
  for (std::uint32_t k : {25u, 26u, 1000u, 65561u, 119999u}) check_holds_sample(r.samples[k - 25], k);
  CHECK(clipped > 0u);
}

TEST_CASE("replay --fifo: missing packets are gaps with their length", "[replay_fifo]") {
  aloft::test::ScratchDir dir;
  FifoFile file;
  file.packets = 2000;
  file.holes = {{500, 20}, {1200, 60}, {1500, 1}};  // 20 ms, 60 ms, 1 ms lost
  const aloft::host::Recording r = read_fifo_recording(dir.write("holes.bin", file.bytes()), 1000);
  REQUIRE(r.samples.size() == 2000u - 81u);
  std::vector<std::pair<std::uint64_t, std::uint64_t>> gaps;  // (at, length)
  for (std::size_t i = 1; i < r.samples.size(); ++i) {
    const auto& s = r.samples[i];
    CHECK(s.gap_before() == (s.t_us - r.samples[i - 1].t_us != 1000u));
    if (s.gap_before()) gaps.emplace_back(s.t_us, s.t_us - r.samples[i - 1].t_us);
  }
  REQUIRE(gaps.size() == 3u);
  CHECK(gaps[0] == std::make_pair(std::uint64_t{520000}, std::uint64_t{21000}));
  CHECK(gaps[1] == std::make_pair(std::uint64_t{1260000}, std::uint64_t{61000}));
  CHECK(gaps[2] == std::make_pair(std::uint64_t{1501000}, std::uint64_t{2000}));
  check_holds_sample(r.samples.back(), 1999);
}

TEST_CASE("replay --fifo: the file reader and the firmware driver agree on the same bytes", "[replay_fifo]") {
  // The fake chip's bytes through the driver, and the same samples' file through the reader.
  aloft_test::FakeIcm42688p chip(&aloft_test::mixed_sample, aloft_test::FakeChipFaults(), 0xFF00);
  aloft::Icm42688pDriver<float> driver(chip.bus(), aloft::icm42688p::DriverSettings());
  REQUIRE(driver.begin() == aloft::Status::ok);
  std::vector<aloft::ImuSample<float>> from_driver;
  const aloft::icm42688p::SampleSink<float> sink{
      &from_driver, [](void* c, const aloft::ImuSample<float>& s) {
        static_cast<std::vector<aloft::ImuSample<float>>*>(c)->push_back(s);
      }};
  while (chip.packets_made() < 3000) {
    chip.advance_us(1000);
    REQUIRE(driver.poll(sink) == aloft::Status::ok);
  }
  aloft::test::ScratchDir dir;
  FifoFile file;
  file.packets = static_cast<std::uint32_t>(from_driver.size());
  const aloft::host::Recording r = read_fifo_recording(dir.write("same.bin", file.bytes()), 1000);
  REQUIRE(r.samples.size() == from_driver.size());
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    REQUIRE(r.samples[i].t_us == from_driver[i].t_us);
    REQUIRE(r.samples[i].accel_m_s2 == from_driver[i].accel_m_s2);
    REQUIRE(r.samples[i].gyro_rad_s == from_driver[i].gyro_rad_s);
    REQUIRE(r.samples[i].flags == from_driver[i].flags);
  }
}

TEST_CASE("replay --fifo: bad bytes get one line naming the file and the offset", "[replay_fifo]") {
  aloft::test::ScratchDir dir;
  FifoFile file;
  file.packets = 10;
  const std::string good = file.bytes();
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.write("empty.bin", ""), 1000), "empty.bin", "byte offset 0",
                       "empty");
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.write("cut.bin", good.substr(0, 16 * 3 + 7)), 1000), "cut.bin",
                       "byte offset 48", "truncated packet (7 of 16 bytes");
  std::string foreign = good;
  foreign[16 * 2] = '\x3C';
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.write("foreign.bin", foreign), 1000), "foreign.bin",
                       "byte offset 32", "header 0x3C");
  // Shifted by one byte: the first header is a data byte.
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.write("shifted.bin", good.substr(1)), 1000), "shifted.bin",
                       "byte offset 0", "not an ICM-42688-P packet 3");
  FifoFile no_data;
  no_data.packets = 5;
  no_data.without_data = 5;
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.write("nodata.bin", no_data.bytes()), 1000), "nodata.bin",
                       "all 5 hold -32768");
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.path("absent.bin"), 1000), "absent.bin", "cannot be opened");
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.write("rate.bin", good), 0), "--odr-hz");
}

TEST_CASE("ICM-42688-P driver RAM, burst buffer included", "[replay_fifo][.footprint]") {
  // Printed for docs/firmware.md (host, 64-bit pointers); the static_assert in the
  // driver's header holds it to 512 bytes on every target.
  std::printf("sizeof(Icm42688pDriver<float>) = %zu, <double> = %zu\n", sizeof(aloft::Icm42688pDriver<float>),
              sizeof(aloft::Icm42688pDriver<double>));
  CHECK(sizeof(aloft::Icm42688pDriver<float>) <= 512u);
}
