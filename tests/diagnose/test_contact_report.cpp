// `aloft diagnose --window` over a throw whose window holds the end of the swing and the
// impact (issue 31 item 4): the contact is cut away and named, in the JSON report and on
// stdout, with the force the hand and the ground applied beyond rotation, and the
// torque-free throw is judged torque-free.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>

#include "run_aloft.hpp"
#include "throw_generator.hpp"

using aloft::test::run_aloft;
using aloft::test::ScratchDir;
using nlohmann::json;

TEST_CASE("diagnose --window: the hand and the impact inside the window are cut away and named",
          "[contact]") {
  ScratchDir dir;
  aloft::test::ThrowSpec spec;
  spec.imu_position_m = Eigen::Vector3d(0.03, -0.01, 0.04);
  spec.gyro_noise_rad_s = 0.01;
  spec.accel_noise_m_s2 = 0.05;
  const aloft::test::GeneratedThrow g = aloft::test::generate_throw(spec);
  const std::string body =
      dir.write("body.json", aloft::test::body_json_text(spec.tensor_kg_m2, spec.imu_position_m));
  const std::string csv = dir.write("imu.csv", aloft::test::imu_csv_text(g));
  char window[64];
  std::snprintf(window, sizeof window, "%.3f:%.3f", g.release_s - 0.060, g.landing_s + 0.008);
  const std::string report = dir.path("report.json");
  const aloft::test::RunResult run = run_aloft(dir, "diagnose --body '" + body + "' --imu '" + csv +
                                                        "' --window " + window + " --json '" + report + "'");
  INFO("stdout: " << run.out << "\nstderr: " << run.err);
  REQUIRE(run.exit_code == 0);
  const json r = json::parse(aloft::test::read_file(report));
  const json& contact = r.at("contact");
  INFO("contact: " << contact.dump());
  REQUIRE(contact.size() == 2);
  CHECK(contact[0].at("where") == "before release");
  CHECK(contact[0].at("cut_to_s").get<double>() >= g.release_s - 0.001);
  CHECK(contact[0].at("cut_to_s").get<double>() <= g.release_s + 0.010);
  CHECK(contact[0].at("beyond_rotation_m_s2").get<double>() >= 10.0);
  CHECK(contact[1].at("where") == "after landing");
  CHECK(contact[1].at("cut_from_s").get<double>() >= g.landing_s - 0.003);
  CHECK(contact[1].at("beyond_rotation_m_s2").get<double>() >= 10.0);
  CHECK(run.out.find("m/s^2 beyond rotation") != std::string::npos);
  // With the swing and the impact in the fit, the nominal model misses by 74 x the noise
  // floor and an impulse is proposed; without them the throw is torque-free, as generated.
  CHECK(r.at("verdict").at("effect") == "none");
}
