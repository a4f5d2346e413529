// examples/throw_imu.csv and examples/throw_body.json: the generator's example throw
// (so they can be made again: ALOFT_WRITE_EXAMPLE_THROW=1 writes them), and the host's
// replay lines (the replay firmware's format, port/cortex_m/replay_example) say exactly
// what `aloft replay --json` says about them. The firmware's lines equal these host lines
// under QEMU (tests/target, target_replay_matches_host): so firmware = aloft replay.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <map>
#include <sstream>

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

// The replay_lines program's output: one map of key -> value per flight.
std::vector<std::map<std::string, std::string>> replay_lines_flights() {
  const aloft::test::ScratchDir& dir = aloft::test::program_scratch();
  const std::string out = dir.path("lines.txt");
  const std::string command =
      std::string("'") + ALOFT_REPLAY_LINES + "' '" + body_path + "' '" + csv_path + "' > '" + out + "'";
  REQUIRE(std::system(command.c_str()) == 0);
  std::vector<std::map<std::string, std::string>> flights;
  std::istringstream lines(read_file(out));
  std::string key, value;
  while (lines >> key >> value) {
    if (key == "flight") flights.emplace_back();
    if (!flights.empty()) flights.back()[key] = value;
    std::getline(lines, value);  // the rest of a header line
  }
  return flights;
}

std::int64_t whole_microseconds(const json& seconds) { return std::llround(double(seconds) * 1e6); }
std::int64_t microseconds_of(const std::string& text) { return std::llround(std::stod(text) * 1e6); }

std::string bits_of(double value) {
  const float f = static_cast<float>(value);
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof bits);
  return std::to_string(bits);
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
  const auto lines = replay_lines_flights();
  REQUIRE(lines.size() == report["flights"].size());
  REQUIRE_FALSE(lines.empty());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const json& f = report["flights"][i];
    auto l = lines[i];
    INFO("flight " << i);
    CHECK(microseconds_of(l["release_s"]) == whole_microseconds(f["release_s"]));
    CHECK(microseconds_of(l["landing_s"]) == whole_microseconds(f["landing_s"]));
    CHECK(l["samples"] == std::to_string(int(f["samples"])));
    CHECK(l["gaps"] == std::to_string(int(f["gaps"])));
    CHECK(l["comparisons"] == std::to_string(int(f["comparisons"])));
    CHECK(l["imu_position_from"] == f["imu_position_from"]);
    CHECK(l["rms_da_rad_bits"] == bits_of(double(f["rms_da_deg"]) / 57.29577951308232));
    CHECK(l["rms_rel_err_bits"] == bits_of(f["rms_rel_err"]));
  }
  // The generator's truth: release at 0.200 s (never before), landing at 0.500 s.
  const json& f = report["flights"][0];
  CHECK(double(f["release_s"]) >= 0.2);
  CHECK(double(f["release_s"]) <= 0.205);
  CHECK(std::abs(double(f["landing_s"]) - 0.5) <= 0.005);
}
