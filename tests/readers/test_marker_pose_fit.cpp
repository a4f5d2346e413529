#include <cmath>
#include <fstream>
#include <limits>
#include <random>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "aloft/dynamics/rotation.hpp"
#include "common/body_file.hpp"
#include "one_line_error.hpp"
#include "readers/body_rates.hpp"
#include "readers/marker_pose_fit.hpp"
#include "readers/trc_reader.hpp"
#include "scratch_files.hpp"

using aloft::host::Body;
using aloft::host::body_rates_from_poses;
using aloft::host::fit_poses;
using aloft::host::MarkerTrial;
using aloft::host::PoseFitReport;

namespace {

Body four_marker_body() {
  Body body;
  body.name = "plate";
  body.markers_m = {{"A", {0.10, 0.00, 0.01}},
                    {"B", {-0.05, 0.08, 0.00}},
                    {"C", {-0.04, -0.09, 0.02}},
                    {"D", {0.01, 0.02, 0.07}}};
  return body;
}

// A body spinning at a constant body rate: q(t) = q0 ⊗ exp(ω t), moving at constant
// velocity. The markers are placed exactly (plus optional noise, metres).
struct KnownMotion {
  Eigen::Vector3d omega_body{3.0, -2.0, 5.0};
  Eigen::Quaterniond q0{Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, -1).normalized())};
  Eigen::Vector3d p0{0.2, 1.1, -0.3};
  Eigen::Vector3d velocity{1.0, 0.5, 2.0};
  double rate_hz = 250.0;
  int frames = 100;

  Eigen::Quaterniond orientation(double t) const {
    return q0 * aloft::quat_exp(Eigen::Vector3d(omega_body * t));
  }
  MarkerTrial markers(const Body& body, double noise_m = 0.0, unsigned seed = 1) const {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, noise_m);
    MarkerTrial trial;
    trial.path = "synthetic.trc";
    trial.format = "trc";
    trial.rate_hz = rate_hz;
    for (const auto& [name, point] : body.markers_m) trial.marker_names.push_back(name);
    for (int f = 0; f < frames; ++f) {
      const double t = f / rate_hz;
      trial.time_s.push_back(t);
      std::vector<Eigen::Vector3d> frame;
      for (const auto& [name, point] : body.markers_m) {
        Eigen::Vector3d p = orientation(t) * point + p0 + velocity * t;
        if (noise_m > 0) p += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
        frame.push_back(p);
      }
      trial.positions_m.push_back(frame);
    }
    return trial;
  }
};

// Name and markers of a body file. Read directly rather than with read_body_file: the
// fit needs only the markers, and the racquet bodies (case12, case15) have principal
// moments that break the triangle inequality (0.01882 + 0.001391 < 0.0207), which
// read_body_file rejects.
Body markers_of_body_file(const std::string& path) {
  std::ifstream in(path);
  const nlohmann::json json = nlohmann::json::parse(in);
  Body body;
  body.name = json.at("name").get<std::string>();
  for (const auto& [name, xyz] : json.at("markers").items()) {
    body.markers_m[name] =
        Eigen::Vector3d(xyz.at(0).get<double>(), xyz.at(1).get<double>(), xyz.at(2).get<double>());
  }
  return body;
}

const Eigen::Vector3d kHidden = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());

}  // namespace

TEST_CASE("fit_poses recovers exact poses, and body rates the exact body ω", "[readers][fit]") {
  const Body body = four_marker_body();
  const KnownMotion motion;
  PoseFitReport report;
  const auto poses = fit_poses(motion.markers(body), body, &report);
  REQUIRE(poses.time_s.size() == 100);
  CHECK(report.gaps.empty());
  CHECK(report.max_rms_residual_m < 1e-12);
  for (std::size_t k = 0; k < poses.time_s.size(); ++k) {
    const double t = poses.time_s[k];
    CHECK(poses.orientation[k].angularDistance(motion.orientation(t)) < 1e-9);
    CHECK((poses.position_m[k] - (motion.p0 + motion.velocity * t)).norm() < 1e-12);
  }
  const auto rates = body_rates_from_poses(poses);
  REQUIRE(rates.omega_body.size() == 99);
  CHECK(rates.pairs_skipped_at_gaps == 0);
  CHECK(rates.time_s[0] == Approx(0.5 / 250.0));
  for (const auto& w : rates.omega_body) CHECK((w - motion.omega_body).norm() < 1e-8);
}

TEST_CASE("frames with fewer than three visible markers are gaps, reported and skipped", "[readers][fit]") {
  const Body body = four_marker_body();
  const KnownMotion motion;
  MarkerTrial markers = motion.markers(body);
  // Frames 10-12: two markers hidden (a gap). Frame 40: one hidden (still posed).
  for (int f = 10; f <= 12; ++f) markers.positions_m[f][0] = markers.positions_m[f][2] = kHidden;
  markers.positions_m[40][3] = kHidden;
  PoseFitReport report;
  const auto poses = fit_poses(markers, body, &report);
  CHECK(poses.time_s.size() == 97);
  REQUIRE(report.gaps.size() == 1);
  CHECK(report.gaps[0].first_frame == 10);
  CHECK(report.gaps[0].last_frame == 12);
  CHECK(report.gaps[0].start_s == Approx(10 / 250.0));
  CHECK(report.gaps[0].end_s == Approx(12 / 250.0));
  CHECK(report.visible_markers[11] == 2);
  CHECK(report.visible_markers[40] == 3);
  CHECK(std::isnan(report.rms_residual_m[11]));
  CHECK(report.rms_residual_m[40] < 1e-12);
  CHECK(report.posed_frames[10] == 13);

  const auto rates = body_rates_from_poses(poses);
  CHECK(rates.pairs_skipped_at_gaps == 1);  // 9 -> 13 straddles the gap
  CHECK(rates.omega_body.size() == 95);
  for (const double t : rates.time_s) CHECK_FALSE((t > 9 / 250.0 && t < 13 / 250.0));
  for (const auto& w : rates.omega_body) CHECK((w - motion.omega_body).norm() < 1e-8);
}

TEST_CASE("three collinear visible markers do not fix a pose", "[readers][fit]") {
  Body body;
  body.name = "stick";
  body.markers_m = {{"A", {-0.1, 0, 0}}, {"B", {0, 0, 0}}, {"C", {0.1, 0, 0}}, {"D", {0, 0.05, 0}}};
  const KnownMotion motion;
  MarkerTrial markers = motion.markers(body);
  markers.positions_m[5][3] = kHidden;  // leaves A, B, C: on one line
  PoseFitReport report;
  const auto poses = fit_poses(markers, body, &report);
  REQUIRE(report.gaps.size() == 1);
  CHECK(report.gaps[0].first_frame == 5);
  CHECK(poses.time_s.size() == 99);
}

TEST_CASE("marker noise shows in the residual", "[readers][fit]") {
  const Body body = four_marker_body();
  const KnownMotion motion;
  PoseFitReport report;
  fit_poses(motion.markers(body, 0.2e-3), body, &report);
  // Six fitted parameters from twelve coordinates leave half the noise variance:
  // RMS residual per marker ≈ 0.2 mm · sqrt(3 · (1 − 6/12)) ≈ 0.24 mm.
  CHECK(report.mean_rms_residual_m == Approx(0.245e-3).epsilon(0.15));
}

TEST_CASE("practice marker trials: poses fit to the marker noise, rates near the true ω0",
          "[readers][fit][shared]") {
  ALOFT_REQUIRE_SHARED_DATA(data);
  std::ifstream truth_file(data + "/practice/truth.json");  // used to score, as its README says
  const nlohmann::json truth = nlohmann::json::parse(truth_file);
  for (const char* name : {"case10", "case11", "case12", "case13", "case14", "case15"}) {
    INFO(name);
    const std::string folder = data + "/practice/" + name;
    const Body body = markers_of_body_file(folder + "/body.json");
    const MarkerTrial markers = aloft::host::read_trc(folder + "/markers.trc");
    PoseFitReport report;
    const auto poses = fit_poses(markers, body, &report);
    // 0.2 mm noise per coordinate, six markers: RMS residual ≈ 0.2·sqrt(3·(1 − 6/18)) mm.
    CHECK(report.mean_rms_residual_m == Approx(0.283e-3).epsilon(0.2));
    CHECK(report.max_rms_residual_m < 0.6e-3);
    const auto rates = body_rates_from_poses(poses);
    CHECK(rates.omega_body.size() + rates.pairs_skipped_at_gaps + 1 == poses.time_s.size());
    // One pair's rate carries ≈0.5 rad/s of noise from 0.2 mm marker noise over 4 ms;
    // |ω0| is 12-14 rad/s, so a frame or sign mistake would miss by far more.
    const auto& w0 = truth.at(name).at("w0");
    const Eigen::Vector3d true_w0(w0.at(0).get<double>(), w0.at(1).get<double>(), w0.at(2).get<double>());
    CHECK((rates.omega_body.front() - true_w0).norm() < 1.5);
  }
}

TEST_CASE("markers named by the body but missing from the file: one error naming them",
          "[readers][fit][bad]") {
  Body body = four_marker_body();
  const KnownMotion motion;
  const MarkerTrial markers = motion.markers(body);
  body.markers_m["E"] = {0, 0, 0.1};
  body.markers_m["F"] = {0, 0.1, 0.1};
  CHECK_ONE_LINE_ERROR(fit_poses(markers, body), "synthetic.trc", "markers E, F", "plate",
                       "it has A, B, C, D");
}

TEST_CASE("too few markers or posable frames: one-line errors", "[readers][fit][bad]") {
  Body body = four_marker_body();
  const KnownMotion motion;
  MarkerTrial markers = motion.markers(body);
  for (auto& frame : markers.positions_m) frame[0] = frame[1] = kHidden;
  CHECK_ONE_LINE_ERROR(fit_poses(markers, body), "synthetic.trc", "0 of 100 frames");
  Body two;
  two.name = "pair";
  two.markers_m = {{"A", {0, 0, 0}}, {"B", {1, 0, 0}}};
  CHECK_ONE_LINE_ERROR(fit_poses(motion.markers(body), two), "synthetic.trc", "at least three");
}

TEST_CASE("Vicon subject prefixes match body marker names", "[readers][fit]") {
  const Body body = four_marker_body();
  MarkerTrial markers = KnownMotion{}.markers(body);
  for (auto& name : markers.marker_names) name = "Subject:" + name;
  CHECK(fit_poses(markers, body).time_s.size() == 100);
}
