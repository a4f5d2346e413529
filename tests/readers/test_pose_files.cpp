#include <cmath>

#include <catch2/catch.hpp>

#include "one_line_error.hpp"
#include "readers/pose_reader.hpp"
#include "scratch_files.hpp"

using aloft::host::read_mot;
using aloft::host::read_pose_csv;
using aloft::test::ScratchDir;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// Angle between two rotations, radians.
double rotation_angle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return a.angularDistance(b);
}

std::string mot(const std::string& header_extra, const std::string& names, const std::string& rows) {
  return "throw\nversion=1\n" + header_extra + "endheader\n" + names + "\n" + rows;
}

}  // namespace

TEST_CASE(".mot free joint: body-fixed X-Y-Z Cardan angles in degrees", "[readers][mot]") {
  ScratchDir dir;
  const auto trial =
      read_mot(dir.write("t.mot", mot("nRows=2\nnColumns=7\ninDegrees=yes\n",
                                      "time\tbox_rotX\tbox_rotY\tbox_rotZ\tbox_tx\tbox_ty\tbox_tz",
                                      "0.000\t90\t0\t0\t1\t2\t3\n0.004\t10\t20\t30\t0.1\t0.2\t0.3\n")));
  CHECK(trial.format == "mot");
  REQUIRE(trial.time_s.size() == 2);
  // 90° about x maps body y onto world z (q maps body to world).
  CHECK((trial.orientation[0] * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitZ()));
  // Body-fixed sequence: R = Rx(a) Ry(b) Rz(c).
  const Eigen::Matrix3d expected = (Eigen::AngleAxisd(10 * kDeg, Eigen::Vector3d::UnitX()) *
                                    Eigen::AngleAxisd(20 * kDeg, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(30 * kDeg, Eigen::Vector3d::UnitZ()))
                                       .toRotationMatrix();
  CHECK(trial.orientation[1].toRotationMatrix().isApprox(expected, 1e-12));
  REQUIRE(trial.position_m.size() == 2);
  CHECK(trial.position_m[0].isApprox(Eigen::Vector3d(1, 2, 3)));
}

TEST_CASE(".mot/.sto columns by name or by OpenSim's free-joint names", "[readers][mot]") {
  ScratchDir dir;
  const Eigen::Quaterniond expected(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()) *
                                    Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitY()) *
                                    Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()));
  SECTION("shuffled named columns, radians, .sto") {
    const auto t = read_mot(dir.write(
        "s.sto", mot("inDegrees=no\n", "ty rz time tx rx tz ry extra", "0 0.3 0 5 0.1 0 0.2 99\n")));
    CHECK(t.format == "sto");
    CHECK(rotation_angle(t.orientation[0], expected) < 1e-12);
    CHECK(t.position_m[0].isApprox(Eigen::Vector3d(5, 0, 0)));
  }
  SECTION("OpenSim FreeJoint default coordinate names") {
    const auto t = read_mot(dir.write(
        "c.mot", mot("inDegrees=no\n",
                     "time free_coord_0 free_coord_1 free_coord_2 free_coord_3 free_coord_4 free_coord_5",
                     "0 0.1 0.2 0.3 1 2 3\n")));
    CHECK(rotation_angle(t.orientation[0], expected) < 1e-12);
    CHECK(t.position_m[0].isApprox(Eigen::Vector3d(1, 2, 3)));
  }
  SECTION("OpenSim's xRotation ... zTranslation spelling") {
    const auto t = read_mot(dir.write(
        "x.mot", mot("inDegrees=no\n",
                     "time blockToGround_xRotation blockToGround_yRotation blockToGround_zRotation "
                     "blockToGround_xTranslation blockToGround_yTranslation blockToGround_zTranslation",
                     "0 0.1 0.2 0.3 1 2 3\n")));
    CHECK(rotation_angle(t.orientation[0], expected) < 1e-12);
    CHECK(t.position_m[0].isApprox(Eigen::Vector3d(1, 2, 3)));
  }
  SECTION("OpenSim 4 state paths: values read, speeds ignored") {
    const auto t = read_mot(
        dir.write("v.sto", mot("inDegrees=no\n",
                               "time /jointset/free/free_coord_0/value /jointset/free/free_coord_0/speed "
                               "/jointset/free/free_coord_1/value /jointset/free/free_coord_2/value "
                               "/jointset/free/free_coord_3/value /jointset/free/free_coord_4/value "
                               "/jointset/free/free_coord_5/value",
                               "0 0.1 9 0.2 0.3 1 2 3\n")));
    CHECK(rotation_angle(t.orientation[0], expected) < 1e-12);
    CHECK(t.position_m[0].isApprox(Eigen::Vector3d(1, 2, 3)));
  }
  SECTION("rotations only") {
    const auto t = read_mot(
        dir.write("r.mot", mot("inDegrees=no\n", "time rx ry rz", "0 0.1 0.2 0.3\n1 0.1 0.2 0.3\n")));
    CHECK(rotation_angle(t.orientation[1], expected) < 1e-12);
    CHECK(t.position_m.empty());
  }
}

TEST_CASE("pose CSV: quaternions, optional position, extra columns ignored", "[readers][pose_csv]") {
  ScratchDir dir;
  // Sample 2 is 60° about x, given to 6 digits; sample 3 is -1, the identity again.
  const auto t =
      read_pose_csv(dir.write("p.csv",
                              "t,qw,qx,qy,qz,wx,wy,wz\n0,1,0,0,0,1,2,3\n0.001,0.866025,0.5,0,0,1,2,3\n"
                              "0.002,-1,0,0,0,1,2,3\n"));
  CHECK(t.format == "pose_csv");
  REQUIRE(t.time_s.size() == 3);
  CHECK(t.position_m.empty());
  CHECK(std::abs(t.orientation[1].norm() - 1.0) < 1e-15);  // normalised
  // -1 is the same rotation as +1; kept in the hemisphere of the sample before it.
  CHECK(t.orientation[2].w() == 1.0);
  const auto with_position = read_pose_csv(dir.write("x.csv", "t,qw,qx,qy,qz,x,y,z\n0,1,0,0,0,0.5,0.25,2\n"));
  REQUIRE(with_position.position_m.size() == 1);
  CHECK(with_position.position_m[0].isApprox(Eigen::Vector3d(0.5, 0.25, 2)));
}

TEST_CASE("bad pose files: one-line errors", "[readers][mot][pose_csv][bad]") {
  ScratchDir dir;
  SECTION("no inDegrees") {
    const auto p = dir.write("a.mot", mot("nRows=1\n", "time rx ry rz", "0 1 2 3\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":4:", "inDegrees");
  }
  SECTION("bad inDegrees") {
    const auto p = dir.write("a.mot", mot("inDegrees=maybe\n", "time rx ry rz", "0 1 2 3\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":3:", "'maybe'");
  }
  SECTION("no endheader") {
    const auto p = dir.write("a.mot", "time rx ry rz\n0 1 2 3\n");
    CHECK_ONE_LINE_ERROR(read_mot(p), p, "endheader");
  }
  SECTION("rows fewer than nRows") {
    const auto p =
        dir.write("a.mot", mot("nRows=3\ninDegrees=yes\n", "time rx ry rz", "0 1 2 3\n0.1 1 2 3\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p, "2 rows where nRows is 3", "truncated");
  }
  SECTION("truncated row") {
    const auto p = dir.write("a.mot", mot("inDegrees=yes\n", "time rx ry rz", "0 1 2 3\n0.1 1 2"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":7:", "truncated");
  }
  SECTION("rotation columns not found") {
    const auto p = dir.write("a.mot", mot("inDegrees=yes\n", "time a b c d", "0 1 2 3 4\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":5:", "no free-joint pose", "time a b c d", "--pose-columns");
  }
  SECTION("nRows beyond any count is refused before it is converted") {
    const auto p = dir.write("a.mot", mot("nRows=1e300\ninDegrees=yes\n", "time rx ry rz", "0 1 2 3\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":3:", "nRows", "1e300");
  }
  SECTION("no time column") {
    const auto p = dir.write("a.mot", mot("inDegrees=yes\n", "rx ry rz", "1 2 3\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":5:", "time");
  }
  SECTION("NaN angle") {
    const auto p = dir.write("a.mot", mot("inDegrees=yes\n", "time rx ry rz", "0 1 nan 3\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":6:", "ry", "not finite");
  }
  SECTION("duplicated time in .mot") {
    const auto p = dir.write("a.mot", mot("inDegrees=yes\n", "time rx ry rz", "0 1 2 3\n0 1 2 3\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":7:", "repeats");
  }
  SECTION("empty .mot") {
    const auto p = dir.write("a.mot", "  \n");
    CHECK_ONE_LINE_ERROR(read_mot(p), p, "empty");
  }
  SECTION("pose CSV without quaternion columns") {
    const auto p = dir.write("a.csv", "t,w,x,y,z\n0,1,0,0,0\n");
    CHECK_ONE_LINE_ERROR(read_pose_csv(p), p + ":1:", "t,qw,qx,qy,qz");
  }
  SECTION("pose CSV with a non-unit quaternion") {
    const auto p = dir.write("a.csv", "t,qw,qx,qy,qz\n0,1,0,0,0\n0.1,0.5,0,0,0\n");
    CHECK_ONE_LINE_ERROR(read_pose_csv(p), p + ":3:", "norm");
  }
  SECTION("pose CSV with time going back") {
    const auto p = dir.write("a.csv", "t,qw,qx,qy,qz\n0.1,1,0,0,0\n0,1,0,0,0\n");
    CHECK_ONE_LINE_ERROR(read_pose_csv(p), p + ":3:", "goes back");
  }
  SECTION("pose CSV header only") {
    const auto p = dir.write("a.csv", "t,qw,qx,qy,qz\n");
    CHECK_ONE_LINE_ERROR(read_pose_csv(p), p, "no samples");
  }
}
