#include <iostream>
#include <sstream>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "c3d_test_writer.hpp"
#include "common/commands.hpp"
#include "one_line_error.hpp"
#include "readers/trial_file.hpp"
#include "scratch_files.hpp"

using aloft::test::ScratchDir;

namespace {

// Runs `aloft inspect ARGS...` in process and returns its stdout as JSON.
nlohmann::json inspect(std::vector<std::string> args) {
  CLI::App app;
  aloft::host::add_inspect_command(app);
  args.insert(args.begin(), "inspect");
  std::reverse(args.begin(), args.end());  // CLI11 takes them last first
  std::ostringstream captured;
  std::streambuf* old = std::cout.rdbuf(captured.rdbuf());
  try {
    app.parse(args);
  } catch (...) {
    std::cout.rdbuf(old);
    throw;
  }
  std::cout.rdbuf(old);
  return nlohmann::json::parse(captured.str());
}

const std::string kTrc =
    "PathFileType\t4\t(X/Y/Z)\tt.trc\n"
    "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n"
    "200\t200\t3\t3\tmm\n"
    "Frame#\tTime\tA\t\t\tB\t\t\tC\t\t\n"
    "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\tX3\tY3\tZ3\n"
    "\n"
    "1\t0.000\t100\t0\t0\t0\t100\t0\t0\t0\t100\n"
    "2\t0.005\t100\t0\t0\t\t\t\t0\t0\t100\n"
    "3\t0.010\t100\t0\t0\t0\t100\t0\t0\t0\t100\n";

}  // namespace

TEST_CASE("inspect a TRC file: SPEC keys, occlusions, and the pose fit with --body", "[readers][inspect]") {
  ScratchDir dir;
  const auto trc = dir.write("m.trc", kTrc);
  const auto summary = inspect({trc});
  CHECK(summary["format"] == "trc");
  CHECK(summary["frames"] == 3);
  CHECK(summary["rate_hz"] == 200.0);
  CHECK(summary["duration_s"].get<double>() == Approx(0.01));
  CHECK(summary["markers"] == nlohmann::json::array({"A", "B", "C"}));
  CHECK(summary["units"] == "mm");
  CHECK(summary["occluded_samples"] == 1);
  CHECK(summary["frames_with_fewer_than_3_markers"] == 1);

  const auto body = dir.write("b.json",
                              R"({"name": "tri", "mass": 1, "inertia": {"principal": [1, 1, 1]},
          "markers": {"A": [0.1, 0, 0], "B": [0, 0.1, 0], "C": [0, 0, 0.1]}})");
  const auto fitted = inspect({trc, "--body", body});
  CHECK(fitted["pose_fit"]["posed_frames"] == 2);
  REQUIRE(fitted["pose_fit"]["gaps"].size() == 1);
  CHECK(fitted["pose_fit"]["gaps"][0]["first_frame"] == 1);
  CHECK(fitted["pose_fit"]["max_rms_residual_m"].get<double>() < 1e-12);
}

TEST_CASE("inspect a C3D file: layout details", "[readers][inspect]") {
  ScratchDir dir;
  aloft::test::C3dContent content;
  content.processor = aloft::test::Processor::mips;
  content.labels = {"M1", "M2", "M3"};
  content.rate_hz = 120.0f;
  content.coordinates.assign(5, std::vector<std::array<double, 3>>(3, {{1.0, 2.0, 3.0}}));
  const auto bytes = aloft::test::write_c3d_bytes(content);
  const auto summary = inspect({dir.write("x.c3d", std::string(bytes.begin(), bytes.end()))});
  CHECK(summary["format"] == "c3d");
  CHECK(summary["frames"] == 5);
  CHECK(summary["rate_hz"] == 120.0);
  CHECK(summary["duration_s"].get<double>() == Approx(4 / 120.0));
  CHECK(summary["markers"].size() == 3);
  CHECK(summary["units"] == "mm");
  CHECK(summary["c3d"]["processor"] == "mips");
  CHECK(summary["c3d"]["data"] == "integer");
}

// A label in another encoding (Latin-1 "É": 0xC9) is not valid UTF-8: the report writes
// U+FFFD where the bad byte was, where it used to end with nlohmann::json's type_error 316.
TEST_CASE("inspect a C3D file whose labels are not UTF-8", "[readers][inspect][bad]") {
  ScratchDir dir;
  aloft::test::C3dContent content;
  content.labels = {"M1", std::string("\xC9PAULE"), "M3"};
  content.rate_hz = 100.0f;
  content.coordinates.assign(4, std::vector<std::array<double, 3>>(3, {{1.0, 2.0, 3.0}}));
  const auto bytes = aloft::test::write_c3d_bytes(content);
  const auto summary = inspect({dir.write("latin1.c3d", std::string(bytes.begin(), bytes.end()))});
  REQUIRE(summary["markers"].size() == 3);
  CHECK(summary["markers"][1].get<std::string>() == "\xEF\xBF\xBDPAULE");
}

TEST_CASE("inspect pose, IMU and segments files, told apart by content", "[readers][inspect]") {
  ScratchDir dir;
  // No telling extension: .txt for all.
  const auto poses = inspect(
      {dir.write("p.txt", "t,qw,qx,qy,qz,x,y,z\n0,1,0,0,0,0,0,0\n0.01,1,0,0,0,0,0,1\n0.02,1,0,0,0,0,0,2\n")});
  CHECK(poses["format"] == "pose_csv");
  CHECK(poses["frames"] == 3);
  CHECK(poses["rate_hz"].get<double>() == Approx(100.0));
  CHECK(poses["duration_s"].get<double>() == Approx(0.02));
  CHECK(poses["has_position"] == true);

  const auto mot =
      inspect({dir.write("m.txt", "x\ninDegrees=yes\nendheader\ntime rx ry rz\n0 0 0 0\n0.5 1 2 3\n")});
  CHECK(mot["format"] == "mot");
  CHECK(mot["rate_hz"].get<double>() == Approx(2.0));

  const auto imu = inspect({dir.write("i.txt", "t,gx,gy,gz,ax,ay,az\n0,3,0,4,0,0,0\n0.001,0,0,1,0,0,0\n")});
  CHECK(imu["format"] == "imu_csv");
  CHECK(imu["frames"] == 2);
  CHECK(imu["rate_hz"].get<double>() == Approx(1000.0));
  CHECK(imu["has_accelerometer"] == true);
  CHECK(imu["max_gyro_rad_s"].get<double>() == Approx(5.0));
  CHECK(imu["columns"] == nlohmann::json({"t", "gx", "gy", "gz", "ax", "ay", "az"}));
  CHECK(imu["has_rotor_speed"] == false);
  CHECK_FALSE(imu.contains("max_abs_rotor_rad_s"));

  // The rotor's speed column is listed, with its peak and what it asks of the body file.
  const auto rotor = inspect(
      {dir.write("r.txt", "t,gx,gy,gz,ax,ay,az,rotor_rad_s\n0,3,0,4,0,0,0,12\n0.001,0,0,1,0,0,0,-640.5\n")});
  CHECK(rotor["columns"] == nlohmann::json({"t", "gx", "gy", "gz", "ax", "ay", "az", "rotor_rad_s"}));
  CHECK(rotor["has_rotor_speed"] == true);
  CHECK(rotor["max_abs_rotor_rad_s"].get<double>() == 640.5);
  CHECK(rotor["notes"].dump().find("rotor_rad_s") != std::string::npos);

  const auto segments = inspect({dir.write("s.txt", "segment,start,end,keep\na,1,2,\nb,3,4,false\n")});
  CHECK(segments["format"] == "segments");
  REQUIRE(segments["segments"].size() == 1);
  CHECK(segments["segments"][0]["segment"] == "a");
}

TEST_CASE("inspect the shared data files", "[readers][inspect][shared]") {
  ALOFT_REQUIRE_SHARED_DATA(data);
  const auto racquet = inspect({data + "/real/racquet/2025-01-16_17-10-11/gyro.csv"});
  CHECK(racquet["format"] == "phyphox");
  CHECK(racquet["rate_hz"].get<double>() == Approx(100.0).epsilon(0.01));
  const auto c3d = inspect({data + "/c3d/sample01/Eb015vr.c3d"});
  CHECK(c3d["c3d"]["processor"] == "dec");
  CHECK(c3d["c3d"]["data"] == "float");
  CHECK(c3d["frames"] == 450);
  const auto damaged = inspect({data + "/c3d/sample18/bad_parameter_section.c3d"});
  CHECK_FALSE(damaged["c3d"]["parameter_damage"].get<std::string>().empty());
}

TEST_CASE("inspect: unknown, empty and mismatched files are one-line errors", "[readers][inspect][bad]") {
  ScratchDir dir;
  SECTION("unknown CSV") {
    const auto p = dir.write("u.csv", "a,b,c\n1,2,3\n");
    CHECK_ONE_LINE_ERROR(inspect({p}), p, "cannot tell the trial format");
  }
  SECTION("empty file") {
    const auto p = dir.write("e.csv", "");
    CHECK_ONE_LINE_ERROR(inspect({p}), p, "empty");
  }
  SECTION("missing file") {
    const auto p = dir.path("missing.csv");
    CHECK_ONE_LINE_ERROR(inspect({p}), p, "cannot open");
  }
  SECTION("--body with a non-marker file") {
    const auto p = dir.write("i.csv", "t,gx,gy,gz\n0,1,2,3\n");
    CHECK_ONE_LINE_ERROR(inspect({p, "--body", "b.json"}), p, "marker files only");
  }
  SECTION("a reader's error passes through") {
    const auto p = dir.write("bad.trc", "PathFileType\t4\n");
    CHECK_ONE_LINE_ERROR(inspect({p}), p, "header");
  }
  SECTION("read_marker_file refuses poses") {
    const auto p = dir.write("p.csv", "t,qw,qx,qy,qz\n0,1,0,0,0\n");
    CHECK_ONE_LINE_ERROR(aloft::host::read_marker_file(p), p, "not marker trajectories");
  }
}
