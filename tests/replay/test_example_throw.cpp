// examples/throw_imu.csv and examples/throw_body.json: the generator's example throw
// (so they can be made again: ALOFT_WRITE_EXAMPLE_THROW=1 writes them), and the host's
// replay lines (the replay firmware's format, port/cortex_m/replay_example) say exactly
// what `aloft replay --json` says about them. The firmware's lines equal these host lines
// under QEMU (tests/target, target_replay_matches_host): so firmware = aloft replay.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "flight_lines_check.hpp"
#include "run_aloft.hpp"
#include "throw_generator.hpp"

using aloft::test::read_file;
using nlohmann::json;

namespace {

const std::string body_path = std::string(ALOFT_EXAMPLES) + "/throw_body.json";
const std::string csv_path = std::string(ALOFT_EXAMPLES) + "/throw_imu.csv";

std::string example_body_text() {
  return aloft::test::body_json_text(aloft::test::example_throw_spec().tensor_kg_m2, Eigen::Vector3d::Zero());
}

// The replay_lines program's output, a flight at a time.
std::vector<aloft::test::FlightLines> replay_lines_flights() {
  const aloft::test::ScratchDir& dir = aloft::test::program_scratch();
  const std::string out = dir.path("lines.txt");
  const std::string command =
      std::string("'") + ALOFT_REPLAY_LINES + "' '" + body_path + "' '" + csv_path + "' > '" + out + "'";
  REQUIRE(std::system(command.c_str()) == 0);
  return aloft::test::flight_lines_of(read_file(out));
}

}  // namespace

TEST_CASE("examples/throw_*: the generator's example throw, byte for byte", "[replay][examples]") {
  const aloft::test::GeneratedThrow g = aloft::test::generate_throw(aloft::test::example_throw_spec());
  if (std::getenv("ALOFT_WRITE_EXAMPLE_THROW")) {
    aloft::test::write_file(csv_path, aloft::test::imu_csv_text(g));
    aloft::test::write_file(body_path, example_body_text());
  }
  CHECK(read_file(csv_path) == aloft::test::imu_csv_text(g));
  CHECK(read_file(body_path) == example_body_text());
}

TEST_CASE("examples/throw_*: the firmware's host lines say what aloft replay --json says",
          "[replay][examples]") {
  const aloft::test::ScratchDir& dir = aloft::test::program_scratch();
  const std::string report_path = dir.path("throw_report.json");
  const auto run = aloft::test::run_aloft("replay --body '" + body_path + "' --imu '" + csv_path +
                                          "' --json '" + report_path + "'");
  INFO("stderr: " << run.err);
  REQUIRE(run.exit_code == 0);
  const json report = json::parse(read_file(report_path));
  aloft::test::check_flight_lines_match_report(replay_lines_flights(), report);
  // The generator's truth: release at 0.200 s (never before), landing at 0.500 s.
  const json& f = report["flights"][0];
  CHECK(double(f["release_s"]) >= 0.2);
  CHECK(double(f["release_s"]) <= 0.205);
  CHECK(std::abs(double(f["landing_s"]) - 0.5) <= 0.005);
}
