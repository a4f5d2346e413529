// The body files in examples/ (docs/file-formats.md, "The body file"): each one read by aloft and used
// the way its kind is used — the paper's cylinder against the study's numbers, the
// marker set to pose a marker trial, the IMU body's sensor rotation in a diagnosis.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "aloft/dynamics/euler_equations.hpp"
#include "common/body_file.hpp"
#include "readers/marker_pose_fit.hpp"
#include "study/paper_cylinder.hpp"
#include "run_aloft.hpp"

namespace fs = std::filesystem;
using aloft::host::Body;

namespace {

const std::string examples = ALOFT_EXAMPLES;

fs::path scratch() { return aloft::test::program_scratch().dir(); }

double angle_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.angularDistance(b);
}

}  // namespace

TEST_CASE("examples/gf_cylinder.json is the seed study's cylinder", "[examples]") {
  const Body body = aloft::host::read_body_file(examples + "/gf_cylinder.json");
  namespace paper = aloft::host::paper;
  const double r = paper::kDiameterM / 2.0, h = paper::kHeightM, m = paper::kMassKg;
  CHECK(body.mass_kg == Approx(m));
  const Eigen::Matrix3d& tensor = body.inertia.tensor();
  CHECK(tensor(0, 0) == Approx(m * (3 * r * r + h * h) / 12.0).epsilon(1e-12));
  CHECK(tensor(1, 1) == Approx(m * (3 * r * r + h * h) / 12.0).epsilon(1e-12));
  CHECK(tensor(2, 2) == Approx(m * r * r / 2.0).epsilon(1e-12));
  CHECK(tensor(0, 1) == 0.0);
}

TEST_CASE("examples/marker_plate.json poses a marker trial", "[examples]") {
  const Body body = aloft::host::read_body_file(examples + "/marker_plate.json");
  REQUIRE(body.markers_m.size() == 6);
  CHECK(body.inertia.tensor()(0, 1) == Approx(-0.00021));  // the matrix entry, as SPEC §2 says

  // Three frames of a known motion, one marker occluded in the second.
  aloft::host::MarkerTrial trial;
  trial.format = "trc";
  trial.rate_hz = 100.0;
  for (const auto& [name, position] : body.markers_m) trial.marker_names.push_back(name);
  std::vector<Eigen::Quaterniond> truth;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Quaterniond q(Eigen::AngleAxisd(0.3 * k + 0.1, Eigen::Vector3d(1, 2, 0.5).normalized()));
    const Eigen::Vector3d origin(0.5, 0.1 * k, 1.2 - 0.05 * k);
    truth.push_back(q);
    trial.time_s.push_back(k / trial.rate_hz);
    std::vector<Eigen::Vector3d> frame;
    for (const auto& [name, position] : body.markers_m) frame.push_back(q * position + origin);
    if (k == 1) frame[2] = Eigen::Vector3d::Constant(NAN);
    trial.positions_m.push_back(frame);
  }
  const aloft::host::PoseTrial poses = aloft::host::fit_poses(trial, body);
  REQUIRE(poses.orientation.size() == 3);
  for (int k = 0; k < 3; ++k) CHECK(angle_between(poses.orientation[k], truth[k]) < 1e-9);
}

TEST_CASE("examples/imu_phone_box.json: its sensor rotation is what makes a diagnosis fit", "[examples]") {
  const std::string body_path = examples + "/imu_phone_box.json";
  const Body body = aloft::host::read_body_file(body_path);
  // A torque-free flight of the body, logged by a gyro mounted as the body file says.
  const fs::path log = scratch() / "imu.csv";
  {
    std::ofstream out(log);
    out << "t,gx,gy,gz\n";
    Eigen::Vector3d omega_body(3.0, 12.0, 1.5);
    const double dt = 1.0 / 500.0;
    for (int k = 0; k <= 500; ++k) {
      const Eigen::Vector3d sensor = body.imu_to_body.conjugate() * omega_body;
      out << k * dt << ',' << sensor.x() << ',' << sensor.y() << ',' << sensor.z() << '\n';
      for (int i = 0; i < 10; ++i) omega_body = aloft::body_rate_rk4_step(body.inertia, omega_body, dt / 10);
    }
  }
  // The same body with its sensor rotation dropped, as a control.
  nlohmann::json without = nlohmann::json::parse(std::ifstream(body_path));
  without.erase("imu");
  const fs::path unrotated = scratch() / "unrotated.json";
  std::ofstream(unrotated) << without.dump();

  const auto baseline_da = [&](const std::string& body_file) {
    const fs::path report = scratch() / "report.json";
    const std::string command = std::string(ALOFT_PROGRAM) + " diagnose --body " + body_file + " --imu " +
                                log.string() + " --json " + report.string() + " > /dev/null";
    REQUIRE(WEXITSTATUS(std::system(command.c_str())) == 0);
    return nlohmann::json::parse(std::ifstream(report))["baseline"]["rms_da_deg"].get<double>();
  };
  CHECK(baseline_da(body_path) < 0.1);
  CHECK(baseline_da(unrotated.string()) > 5.0);
}
