// The STM32F405 replay image's host side (port/host_tools): make_fifo_throw
// turns examples/throw_imu.csv into FIFO bytes, and fifo_replay_lines prints the host's
// result for them in the image's format. Here those lines must say exactly what
// `aloft replay --fifo --json` says about the same bytes; under QEMU the image's lines
// equal fifo_replay_lines' (tests/stm32f405, stm32f405_replay): so firmware = aloft replay.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <string>

#include "flight_lines_check.hpp"
#include "run_aloft.hpp"

using aloft::test::read_file;
using nlohmann::json;

namespace {

const std::string body_path = std::string(ALOFT_EXAMPLES) + "/throw_body.json";
const std::string csv_path = std::string(ALOFT_EXAMPLES) + "/throw_imu.csv";

void run_program(const std::string& command) {
  INFO(command);
  REQUIRE(std::system(command.c_str()) == 0);
}

}  // namespace

TEST_CASE("the STM32F405 replay's host lines say what aloft replay --fifo --json says", "[replay][fifo]") {
  const aloft::test::ScratchDir& dir = aloft::test::program_scratch();
  const std::string fifo = dir.path("throw_fifo.bin"), lines = dir.path("lines.txt");
  run_program(std::string("'") + ALOFT_MAKE_FIFO_THROW + "' '" + body_path + "' '" + csv_path + "' '" +
              dir.path("throw.cpp") + "' '" + fifo + "'");
  CHECK(read_file(fifo).size() == 550u * 16u);  // every CSV row one packet
  run_program(std::string("'") + ALOFT_FIFO_REPLAY_LINES + "' '" + body_path + "' '" + fifo + "' 1000 > '" +
              lines + "'");
  const std::string report_path = dir.path("report.json");
  const auto run = aloft::test::run_aloft("replay --body '" + body_path + "' --fifo '" + fifo +
                                          "' --odr-hz 1000 --json '" + report_path + "'");
  INFO("stderr: " << run.err);
  REQUIRE(run.exit_code == 0);
  const json report = json::parse(read_file(report_path));
  aloft::test::check_flight_lines_match_report(aloft::test::flight_lines_of(read_file(lines)), report);
}

TEST_CASE(
    "aloft replay --fifo: empty reads and a cut tail are survived, every flight kept; exit 2 only when "
    "nothing decodes",
    "[replay][fifo]") {
  const aloft::test::ScratchDir& dir = aloft::test::program_scratch();
  const std::string fifo = dir.path("throw_fifo_faults.bin");
  run_program(std::string("'") + ALOFT_MAKE_FIFO_THROW + "' '" + body_path + "' '" + csv_path + "' '" +
              dir.path("throw_faults.cpp") + "' '" + fifo + "'");
  const std::string plain = read_file(fifo);
  REQUIRE(plain.size() == 550u * 16u);
  const auto replay = [&](const std::string& name, const std::string& bytes) {
    const std::string path = dir.write(name, bytes);
    return aloft::test::run_aloft("replay --body '" + body_path + "' --fifo '" + path +
                                  "' --odr-hz 1000 --json '" + path + ".json'");
  };
  const auto want = replay("plain.bin", plain);
  REQUIRE(want.exit_code == 0);
  const json want_report = json::parse(read_file(dir.path("plain.bin.json")));
  REQUIRE_FALSE(want_report["flights"].empty());

  // Empty reads in both forms during the flight, and the power cut 7 bytes into a packet.
  std::string faulty = plain.substr(0, 16 * 100) + '\x80' + plain.substr(16 * 100, 16 * 150) + '\x80' +
                       std::string(15, '\0') + plain.substr(16 * 250) + '\x80' + std::string(15, '\x80') +
                       plain.substr(0, 7);
  const auto run = replay("faulty.bin", faulty);
  INFO("stderr: " << run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(aloft::test::count_lines(run.err) == 1u);
  CHECK(run.err.find("byte offset " + std::to_string(faulty.size() - 7) +
                     ": the last packet is cut (7 of 16") != std::string::npos);
  CHECK(run.out.find("3 empty reads, 7 bytes skipped") != std::string::npos);
  const json report = json::parse(read_file(dir.path("faulty.bin.json")));
  CHECK(report["stream"]["empty_reads"] == 3);
  CHECK(report["stream"]["bytes_skipped"] == 7);
  CHECK(report["stream"]["resyncs"] == 0);
  CHECK(report["stream"]["samples"] == want_report["stream"]["samples"]);
  CHECK(report["flights"] == want_report["flights"]);

  // Nothing decodes: one line, exit 2.
  for (const std::string& nothing : {std::string(48, '\x80'), plain.substr(0, 15), std::string(40, '\x3C')}) {
    const auto refused = replay("nothing.bin", nothing);
    CHECK(refused.exit_code == 2);
    CHECK(aloft::test::count_lines(refused.err) == 1u);
    CHECK(refused.err.find("no ICM-42688-P packet 3") != std::string::npos);
  }
}
