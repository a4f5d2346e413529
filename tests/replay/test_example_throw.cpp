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

#include "aloft/onboard/tensor_estimator.hpp"
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

// The tensor the example throw shows, from its airborne samples (the generator's release
// to its landing) through the onboard estimator in float with its default settings: the
// ratios within 1 % of the body file's.
TEST_CASE("examples/throw_*: the flight's own tensor estimate, ratios within 1 % of the body file",
          "[replay][examples][tensor]") {
  const aloft::test::ThrowSpec spec = aloft::test::example_throw_spec();
  const aloft::test::GeneratedThrow g = aloft::test::generate_throw(spec);
  aloft::InertiaTensor<float> body;
  REQUIRE(aloft::InertiaTensor<float>::make_from_tensor(spec.tensor_kg_m2.cast<float>(), body) ==
          aloft::Status::ok);
  const aloft::TensorEstimatorSettings<float> settings;
  const aloft::Rotor<float> no_rotor;
  aloft::TensorEstimator<float> estimator;
  const aloft::TensorEstimatorInputs<float> inputs{settings, body, no_rotor};
  estimator.start();
  double previous_t = -1;
  for (std::size_t i = 0; i < g.t_s.size(); ++i) {
    if (g.t_s[i] < g.release_s || g.t_s[i] >= g.landing_s) continue;
    const auto dt_us =
        previous_t < 0 ? 0u : static_cast<std::uint32_t>(std::lround((g.t_s[i] - previous_t) * 1e6));
    estimator.add(g.gyro_rad_s[i].cast<float>(), g.gyro_rad_s[i - 1].cast<float>(), 0.0f, dt_us, inputs);
    previous_t = g.t_s[i];
  }
  aloft::TensorEstimate<float> e;
  estimator.finish(inputs, e);
  REQUIRE(e.determined);
  const aloft::Vec3<float>& m = body.principal_moments();
  INFO("ratios " << e.ratio(0) << " " << e.ratio(1) << " against " << m(0) / m(2) << " " << m(1) / m(2));
  CHECK(std::abs(e.ratio(0) / (m(0) / m(2)) - 1.0f) < 0.01f);
  CHECK(std::abs(e.ratio(1) / (m(1) / m(2)) - 1.0f) < 0.01f);
}

// The same through `aloft replay`: the pipeline feeds the estimate the samples it dated
// airborne (0.201-0.499 s), and the report carries it (SPEC §5 tensor_estimate).
TEST_CASE("examples/throw_*: aloft replay reports the flight's tensor, ratios within 1 % of the body file",
          "[replay][examples][tensor]") {
  const aloft::test::ScratchDir& dir = aloft::test::program_scratch();
  const std::string report_path = dir.path("throw_tensor.json");
  const auto run = aloft::test::run_aloft("replay --body '" + body_path + "' --imu '" + csv_path +
                                          "' --json '" + report_path + "'");
  REQUIRE(run.exit_code == 0);
  CHECK(run.out.find("tensor estimate") != std::string::npos);
  const json t = json::parse(read_file(report_path))["flights"][0]["tensor_estimate"];
  INFO(t.dump());
  REQUIRE(t["determined"] == true);
  aloft::InertiaTensor<double> body;
  REQUIRE(aloft::InertiaTensor<double>::make_from_tensor(aloft::test::example_throw_spec().tensor_kg_m2,
                                                         body) == aloft::Status::ok);
  const aloft::Vec3<double>& m = body.principal_moments();
  for (int i = 0; i < 2; ++i) {
    const double ratio = t["principal_ratios"][i].get<double>(), truth = m(i) / m(2);
    CHECK(std::abs(ratio / truth - 1.0) < 0.01);
    CHECK(t["principal_ratios_95"][i][0].get<double>() < ratio);
    CHECK(t["principal_ratios_95"][i][1].get<double>() > ratio);
  }
  CHECK(t["axes"].size() == 4);
  CHECK(t["axes_95_deg"].size() == 3);
  CHECK(t["principal_kg_m2"].is_null());
  CHECK(t["principal_kg_m2_95"].is_null());
}
