// The `replay --fifo` file reader: FIFO bytes encoded from the datasheet become the
// samples that made them, bit for bit, through the firmware's decoder; holes come out as
// gaps of the right length; bad bytes get one line naming the file and the byte offset.
#include <catch2/catch.hpp>

#include <cstdio>

#include "aloft/sensor/icm42688p_driver.hpp"
#include "common/warning.hpp"
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

TEST_CASE("replay --fifo: empty reads (0x80) are counted, the byte alone or a whole slot", "[replay_fifo]") {
  aloft::test::ScratchDir dir;
  FifoFile plain;
  plain.packets = 100;
  FifoFile file = plain;
  using E = FifoFile::EmptyRead;
  file.empty_reads = {E{0, false},       E{10, false},      E{10, false},      E{20, true, 0x80},
                      E{30, true, 0x00}, E{40, true, 0xFF}, E{50, false},      E{50, true, 0x80},
                      E{60, true, 0x80}, E{60, true, 0x80}, E{100, true, 0x00}};
  aloft::host::WarningCapture warnings;
  const aloft::host::Recording r = read_fifo_recording(dir.write("empty_reads.bin", file.bytes()), 1000);
  const aloft::host::Recording want = read_fifo_recording(dir.write("plain.bin", plain.bytes()), 1000);
  CHECK(file.bytes().size() == 100u * 16u + 4u + 7u * 16u);  // 4 bytes alone, 7 whole slots
  CHECK(r.empty_reads == 11u);
  CHECK(r.bytes_skipped == 0u);
  CHECK(r.resyncs == 0u);
  CHECK(warnings.messages().empty());
  REQUIRE(r.samples.size() == 100u);
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    REQUIRE(r.samples[i].t_us == want.samples[i].t_us);
    REQUIRE(r.samples[i].accel_m_s2 == want.samples[i].accel_m_s2);
    REQUIRE(r.samples[i].flags == want.samples[i].flags);
  }
}

TEST_CASE("replay --fifo: a cut last packet is a warning naming its offset; all before it is kept",
          "[replay_fifo]") {
  aloft::test::ScratchDir dir;
  FifoFile file;
  file.packets = 10;
  file.cut_tail = 7;
  {
    aloft::host::WarningCapture warnings;
    const aloft::host::Recording r = read_fifo_recording(dir.write("cut.bin", file.bytes()), 1000);
    CHECK(r.samples.size() == 10u);
    CHECK(r.bytes_skipped == 7u);
    CHECK(r.resyncs == 0u);
    REQUIRE(warnings.messages().size() == 1u);
    CHECK(warnings.contains("cut.bin: byte offset 160: the last packet is cut (7 of 16 bytes"));
  }
  // A fixed-size burst cut inside an empty slot.
  file.cut_tail = 0;
  file.empty_reads = {FifoFile::EmptyRead{10, true, 0x00}};
  aloft::host::WarningCapture warnings;
  const aloft::host::Recording r =
      read_fifo_recording(dir.write("cut_slot.bin", file.bytes().substr(0, 160 + 5)), 1000);
  CHECK(r.samples.size() == 10u);
  CHECK(r.empty_reads == 0u);
  CHECK(r.bytes_skipped == 5u);
  CHECK(warnings.contains("byte offset 160: the last empty read is cut (5 of 16 bytes"));
}

TEST_CASE("replay --fifo: a foreign header is skipped to the next packet boundary, counted",
          "[replay_fifo]") {
  aloft::test::ScratchDir dir;
  FifoFile file;
  file.packets = 100;
  file.foreign_header_packet = 40;
  {
    aloft::host::WarningCapture warnings;
    const aloft::host::Recording r = read_fifo_recording(dir.write("foreign.bin", file.bytes()), 1000);
    CHECK(r.resyncs == 1u);
    CHECK(r.bytes_skipped == 16u);
    REQUIRE(r.samples.size() == 99u);
    CHECK(r.samples[40].t_us == 41000u);  // sample 40 is gone: a gap of 2 ms
    CHECK(r.samples[40].gap_before());
    check_holds_sample(r.samples[40], 41);
    REQUIRE(warnings.messages().size() == 1u);
    CHECK(warnings.contains("foreign.bin: byte offset 640: header 0x3C"));
    CHECK(warnings.contains("16 bytes skipped"));
  }
  // Shifted by one byte: the first "header" is a data byte; the stream starts at 15.
  FifoFile ten;
  ten.packets = 10;
  aloft::host::WarningCapture warnings;
  const aloft::host::Recording shifted =
      read_fifo_recording(dir.write("shifted.bin", ten.bytes().substr(1)), 1000);
  CHECK(shifted.resyncs == 1u);
  CHECK(shifted.bytes_skipped == 15u);
  REQUIRE(shifted.samples.size() == 9u);
  check_holds_sample(shifted.samples[0], 1);
  // Junk between two packets: skipped, nothing lost.
  std::string junk = ten.bytes();
  junk.insert(16 * 4, "\x3C\x11\x68\x33\x44", 5);
  const aloft::host::Recording r = read_fifo_recording(dir.write("junk.bin", junk), 1000);
  CHECK(r.resyncs == 1u);
  CHECK(r.bytes_skipped == 5u);
  CHECK(r.samples.size() == 10u);
  CHECK(warnings.contains("junk.bin: byte offset 64: header 0x3C"));
  // 0xFF (a bus floating high) has HEADER_MSG's bit but is not 0x80: foreign, not empty.
  std::string high = ten.bytes();
  high.insert(16 * 6, "\xFF", 1);
  const aloft::host::Recording h = read_fifo_recording(dir.write("high.bin", high), 1000);
  CHECK(h.resyncs == 1u);
  CHECK(h.bytes_skipped == 1u);
  CHECK(h.empty_reads == 0u);
  CHECK(h.samples.size() == 10u);
}

TEST_CASE("replay --fifo: the fake chip's bytes, faults included: the reader keeps what the driver keeps",
          "[replay_fifo]") {
  // Every byte the driver read from FIFO_DATA, tapped as a logic analyser would: 0x80
  // bursts, a garbled header, and power lost 7 bytes before the end of the last burst.
  aloft_test::FakeChipFaults faults;
  faults.garbled_header_packet = 1500;
  aloft_test::FakeIcm42688p chip(&aloft_test::mixed_sample, faults, 0xFF00);
  std::string tapped;
  chip.tap_fifo_data(
      [](void* c, const std::uint8_t* b, std::uint16_t n) {
        static_cast<std::string*>(c)->append(reinterpret_cast<const char*>(b), n);
      },
      &tapped);
  aloft::Icm42688pDriver<float> driver(chip.bus(), aloft::icm42688p::DriverSettings());
  REQUIRE(driver.begin() == aloft::Status::ok);
  std::vector<aloft::ImuSample<float>> from_driver;
  const aloft::icm42688p::SampleSink<float> sink{
      &from_driver, [](void* c, const aloft::ImuSample<float>& s) {
        static_cast<std::vector<aloft::ImuSample<float>>*>(c)->push_back(s);
      }};
  while (chip.packets_made() < 3000) {
    if (chip.packets_made() == 1000) chip.empty_bursts(3);
    if (chip.packets_made() == 2000) {
      chip.advance_us(5000);  // with the next ms, 6 packets wait: the first burst reads 0x80
      chip.empty_bursts(1);
    }
    chip.advance_us(1000);
    REQUIRE(driver.poll(sink) == aloft::Status::ok);
  }
  const aloft::icm42688p::DriverCounters& c = driver.counters();
  CHECK(c.resyncs == 1u);
  CHECK(c.bytes_skipped == 16u);
  const std::uint32_t empty_slots = chip.empty_reads_sent();
  // 1, 2, 3 packets waiting; then 6, of which the first burst takes kBurstPackets (4).
  constexpr std::uint32_t burst = aloft::Icm42688pDriver<float>::kBurstPackets;
  CHECK(empty_slots == 1u + 2u + 3u + (burst < 6u ? burst : 6u));
  REQUIRE(tapped.size() % 16u == 0u);
  aloft::test::ScratchDir dir;
  aloft::host::WarningCapture warnings;
  const aloft::host::Recording r =
      read_fifo_recording(dir.write("tapped.bin", tapped.substr(0, tapped.size() - 7)), 1000);
  CHECK(r.empty_reads == empty_slots);
  CHECK(r.resyncs == 1u);
  CHECK(r.bytes_skipped == 16u + 9u);  // the garbled packet, and the 9 bytes of the cut one
  CHECK(warnings.contains("the last packet is cut (9 of 16 bytes"));
  // The same samples, but the last one, whose packet the power cut took.
  REQUIRE(r.samples.size() == from_driver.size() - 1u);
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    REQUIRE(r.samples[i].t_us == from_driver[i].t_us);
    REQUIRE(r.samples[i].accel_m_s2 == from_driver[i].accel_m_s2);
    REQUIRE(r.samples[i].gyro_rad_s == from_driver[i].gyro_rad_s);
    REQUIRE(r.samples[i].flags == from_driver[i].flags);
  }
}

TEST_CASE("replay --fifo: one line naming the file, only where nothing decodes", "[replay_fifo]") {
  aloft::test::ScratchDir dir;
  FifoFile file;
  file.packets = 10;
  const std::string good = file.bytes();
  const aloft::host::WarningCapture quiet;
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.write("empty.bin", ""), 1000), "empty.bin", "byte offset 0",
                       "empty");
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.write("junk.bin", std::string(64, '\x3C')), 1000), "junk.bin",
                       "no ICM-42688-P packet 3 in 64 bytes (0 empty reads, 64 bytes skipped)");
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.write("only_empty.bin", std::string(48, '\x80')), 1000),
                       "only_empty.bin",
                       "no ICM-42688-P packet 3 in 48 bytes (3 empty reads, 0 bytes skipped)");
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.write("cut_only.bin", good.substr(0, 9)), 1000),
                       "cut_only.bin", "no ICM-42688-P packet 3 in 9 bytes (0 empty reads, 9 bytes skipped)");
  FifoFile no_data;
  no_data.packets = 5;
  no_data.without_data = 5;
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.write("nodata.bin", no_data.bytes()), 1000), "nodata.bin",
                       "all 5 hold -32768");
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.path("absent.bin"), 1000), "absent.bin", "cannot be opened");
  CHECK_ONE_LINE_ERROR(read_fifo_recording(dir.write("rate.bin", good), 0), "--odr-hz");
}

TEST_CASE("ICM-42688-P driver RAM, burst buffer included", "[replay_fifo][.footprint]") {
  // Printed for docs/icm42688p.md (host, 64-bit pointers); the static_assert in the
  // driver's header holds it to 512 bytes on every target.
  std::printf("sizeof(Icm42688pDriver<float>) = %zu, <double> = %zu\n", sizeof(aloft::Icm42688pDriver<float>),
              sizeof(aloft::Icm42688pDriver<double>));
  CHECK(sizeof(aloft::Icm42688pDriver<float>) <= 512u);
}
