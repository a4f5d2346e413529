// A .mot/.sto pose comes from names, never from column positions (issue 15): files that
// hold no free joint are refused, and the user can name the pose by columns or by an
// OpenSim model's joint.
#include <cmath>

#include <catch2/catch.hpp>

#include "one_line_error.hpp"
#include "readers/pose_reader.hpp"
#include "readers/trial_file.hpp"
#include "scratch_files.hpp"

using aloft::host::PoseNaming;
using aloft::host::read_mot;
using aloft::test::ScratchDir;

namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

std::string sto(const std::string& names, const std::string& rows,
                const std::string& header = "inDegrees=no\n") {
  return "result\nversion=1\n" + header + "endheader\n" + names + "\n" + rows;
}

Eigen::Matrix3d about(const Eigen::Vector3d& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

// An OpenSim 4 model with one joint, `joint_xml` (its frames and transform inside).
std::string osim4(const std::string& joint_xml) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\" ?>\n<OpenSimDocument Version=\"40000\">\n"
         "<Model name=\"m\"><JointSet name=\"jointset\"><objects>\n" +
         joint_xml + "</objects></JointSet></Model></OpenSimDocument>\n";
}

std::string transform_axis(
    const std::string& name, const std::string& coordinate, const std::string& axis,
    const std::string& function =
        "<LinearFunction name=\"function\"><coefficients> 1 0</coefficients></LinearFunction>") {
  return "<TransformAxis name=\"" + name + "\"><coordinates>" + coordinate + "</coordinates><axis>" + axis +
         "</axis>" + function + "</TransformAxis>\n";
}

// A pelvis-like CustomJoint to ground: rotation1 about z (tilt), rotation2 about x
// (list), rotation3 about y (rotation), then translations along x, y, z.
std::string pelvis_joint(const std::string& frames = "", const std::string& parent = "ground") {
  return "<CustomJoint name=\"ground_pelvis\"><socket_parent_frame>" + parent +
         "</socket_parent_frame><socket_child_frame>pelvis</socket_child_frame>"
         "<coordinates><Coordinate name=\"tilt\"/><Coordinate name=\"list\"/><Coordinate name=\"rot\"/>"
         "<Coordinate name=\"tx\"/><Coordinate name=\"ty\"/><Coordinate name=\"tz\"/></coordinates>" +
         frames + "<SpatialTransform>" + transform_axis("rotation1", "tilt", "0 0 1") +
         transform_axis("rotation2", "list", "1 0 0") + transform_axis("rotation3", "rot", "0 1 0") +
         transform_axis("translation1", "tx", "1 0 0") + transform_axis("translation2", "ty", "0 1 0") +
         transform_axis("translation3", "tz", "0 0 1") + "</SpatialTransform></CustomJoint>\n";
}

const std::string kPelvisColumns = "time tilt list rot tx ty tz";
const std::string kPelvisRow = "0 30 -20 50 0.1 0.2 0.3\n";  // degrees

}  // namespace

TEST_CASE("files without a free joint are refused, never read by column position", "[readers][mot][naming]") {
  ScratchDir dir;
  SECTION("centre-of-mass position state_0..2") {
    const auto p = dir.write("com.sto", sto("time state_0 state_1 state_2", "0 0.1 0.2 0.3\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":5:", "no free-joint pose", "state_0", "--pose-columns", "--osim");
  }
  SECTION("six muscle excitations") {
    const auto p =
        dir.write("exc.sto", sto("time soleus gasmed tibant vasint recfem bfsh", "0 .1 .2 .3 .4 .5 .6\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":5:", "no free-joint pose", "soleus");
  }
  SECTION("a slider's position, speed and actuator") {
    const auto p = dir.write("slider.sto", sto("time slider_x slider_x_u actuator", "0 1 2 3\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":5:", "no free-joint pose");
  }
  SECTION("coordinates and their speeds") {
    const auto p = dir.write("q.sto", sto("time q1 q2 q3 q1_u q2_u q3_u", "0 1 2 3 4 5 6\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":5:", "no free-joint pose", "q1_u");
  }
  SECTION("neither a pose nor inDegrees: the pose is named first") {
    const auto p = dir.write("both.sto", sto("time a b c", "0 1 2 3\n", ""));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":4:", "no free-joint pose");
  }
  SECTION("two free joints") {
    const auto p = dir.write("two.sto", sto("time a_rx a_ry a_rz b_rx b_ry b_rz", "0 1 2 3 4 5 6\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":5:", "2 free joints", "--pose-columns");
  }
  SECTION("rotations of different joints do not make one") {
    const auto p = dir.write("mix.sto", sto("time a_rx a_ry b_rz", "0 1 2 3\n"));
    CHECK_ONE_LINE_ERROR(read_mot(p), p + ":5:", "no free-joint pose");
  }
}

TEST_CASE("--pose-columns names the pose, with its rotation sequence", "[readers][mot][naming]") {
  ScratchDir dir;
  const auto p = dir.write(
      "q.sto", sto("time q1 q2 q3 q1_u q2_u q3_u x y z", "0 10 20 30 4 5 6 1 2 3\n", "inDegrees=yes\n"));
  PoseNaming naming;
  naming.columns = {"q1", "q2", "q3", "x", "y", "z"};
  SECTION("default body-fixed x-y-z") {
    const auto t = read_mot(p, naming);
    const Eigen::Matrix3d expected = about(Eigen::Vector3d::UnitX(), 10 * kDeg) *
                                     about(Eigen::Vector3d::UnitY(), 20 * kDeg) *
                                     about(Eigen::Vector3d::UnitZ(), 30 * kDeg);
    CHECK(t.orientation[0].toRotationMatrix().isApprox(expected, 1e-12));
    CHECK(t.position_m[0].isApprox(Eigen::Vector3d(1, 2, 3)));
  }
  SECTION("sequence z-x-z") {
    naming.sequence = "zxz";
    const auto t = read_mot(p, naming);
    const Eigen::Matrix3d expected = about(Eigen::Vector3d::UnitZ(), 10 * kDeg) *
                                     about(Eigen::Vector3d::UnitX(), 20 * kDeg) *
                                     about(Eigen::Vector3d::UnitZ(), 30 * kDeg);
    CHECK(t.orientation[0].toRotationMatrix().isApprox(expected, 1e-12));
  }
  SECTION("rotations only") {
    naming.columns = {"q3", "q2", "q1"};
    const auto t = read_mot(p, naming);
    CHECK(t.position_m.empty());
  }
  SECTION("a column that is not there") {
    naming.columns = {"q1", "q2", "q4"};
    CHECK_ONE_LINE_ERROR(read_mot(p, naming), p + ":5:", "no column q4", "q1_u");
  }
  SECTION("a wrong count or sequence") {
    naming.columns = {"q1", "q2"};
    CHECK_ONE_LINE_ERROR(read_mot(p, naming), "--pose-columns", "not 2");
    naming.columns = {"q1", "q2", "q3"};
    naming.sequence = "xxy";
    CHECK_ONE_LINE_ERROR(read_mot(p, naming), "--pose-sequence", "'xxy'");
  }
  SECTION("a pose CSV takes no naming") {
    const auto csv = dir.write("p.csv", "t,qw,qx,qy,qz\n0,1,0,0,0\n");
    CHECK_ONE_LINE_ERROR(aloft::host::read_pose_file(csv, naming), csv, ".mot/.sto");
  }
}

TEST_CASE("--osim --joint: a CustomJoint's SpatialTransform order, against a hand-computed rotation",
          "[readers][mot][naming][osim]") {
  ScratchDir dir;
  const auto p = dir.write("ik.mot", sto(kPelvisColumns, kPelvisRow, "inDegrees=yes\n"));
  PoseNaming naming;
  naming.joint = "ground_pelvis";
  SECTION("rotation1 (z), then rotation2 (x), then rotation3 (y), body-fixed") {
    naming.osim_path = dir.write("m.osim", osim4(pelvis_joint()));
    const auto t = read_mot(p, naming);
    // Hand-computed: R = Rz(30°) · Rx(-20°) · Ry(50°).
    const double a = 30 * kDeg, b = -20 * kDeg, c = 50 * kDeg;
    const Eigen::Matrix3d rz{{std::cos(a), -std::sin(a), 0}, {std::sin(a), std::cos(a), 0}, {0, 0, 1}};
    const Eigen::Matrix3d rx{{1, 0, 0}, {0, std::cos(b), -std::sin(b)}, {0, std::sin(b), std::cos(b)}};
    const Eigen::Matrix3d ry{{std::cos(c), 0, std::sin(c)}, {0, 1, 0}, {-std::sin(c), 0, std::cos(c)}};
    CHECK(t.orientation[0].toRotationMatrix().isApprox(rz * rx * ry, 1e-12));
    CHECK_FALSE(t.orientation[0].toRotationMatrix().isApprox(ry * rx * rz, 1e-3));  // order matters here
    CHECK(t.position_m[0].isApprox(Eigen::Vector3d(0.1, 0.2, 0.3)));
  }
  SECTION("a parent offset frame on ground moves and turns the body") {
    const std::string frames =
        "<frames><PhysicalOffsetFrame name=\"ground_offset\"><socket_parent>/ground</socket_parent>"
        "<translation>1 0 0</translation><orientation>0 0 1.5707963267948966</orientation>"
        "</PhysicalOffsetFrame></frames>";
    naming.osim_path = dir.write("o.osim", osim4(pelvis_joint(frames, "ground_offset")));
    const auto t = read_mot(p, naming);
    const Eigen::Matrix3d turn = about(Eigen::Vector3d::UnitZ(), kDeg * 90);
    const Eigen::Matrix3d joint = about(Eigen::Vector3d::UnitZ(), 30 * kDeg) *
                                  about(Eigen::Vector3d::UnitX(), -20 * kDeg) *
                                  about(Eigen::Vector3d::UnitY(), 50 * kDeg);
    CHECK(t.orientation[0].toRotationMatrix().isApprox(turn * joint, 1e-12));
    CHECK(t.position_m[0].isApprox(Eigen::Vector3d(1, 0, 0) + turn * Eigen::Vector3d(0.1, 0.2, 0.3), 1e-12));
  }
  SECTION("a linear function scales the coordinate") {
    std::string joint = pelvis_joint();
    const std::string unit = "<coefficients> 1 0</coefficients>";
    joint.replace(joint.find(unit), unit.size(), "<coefficients>2 0.1</coefficients>");  // rotation1
    naming.osim_path = dir.write("f.osim", osim4(joint));
    const auto t = read_mot(p, naming);
    const Eigen::Matrix3d expected = about(Eigen::Vector3d::UnitZ(), 2 * 30 * kDeg + 0.1) *
                                     about(Eigen::Vector3d::UnitX(), -20 * kDeg) *
                                     about(Eigen::Vector3d::UnitY(), 50 * kDeg);
    CHECK(t.orientation[0].toRotationMatrix().isApprox(expected, 1e-12));
  }
}

TEST_CASE("--osim --joint: FreeJoint and OpenSim 3 layouts", "[readers][mot][naming][osim]") {
  ScratchDir dir;
  PoseNaming naming;
  naming.joint = "blockToGround";
  const auto p = dir.write("ik.mot", sto("time c0 c1 c2 c3 c4 c5", "0 0.1 0.2 0.3 1 2 3\n"));
  const Eigen::Matrix3d xyz = about(Eigen::Vector3d::UnitX(), 0.1) * about(Eigen::Vector3d::UnitY(), 0.2) *
                              about(Eigen::Vector3d::UnitZ(), 0.3);
  SECTION("OpenSim 4 FreeJoint") {
    naming.osim_path = dir.write(
        "f.osim", osim4("<FreeJoint name=\"blockToGround\"><socket_parent_frame>/ground</socket_parent_frame>"
                        "<socket_child_frame>block</socket_child_frame><coordinates><Coordinate "
                        "name=\"c0\"/><Coordinate name=\"c1\"/>"
                        "<Coordinate name=\"c2\"/><Coordinate name=\"c3\"/><Coordinate "
                        "name=\"c4\"/><Coordinate name=\"c5\"/>"
                        "</coordinates></FreeJoint>"));
    const auto t = read_mot(p, naming);
    CHECK(t.orientation[0].toRotationMatrix().isApprox(xyz, 1e-12));
    CHECK(t.position_m[0].isApprox(Eigen::Vector3d(1, 2, 3)));
  }
  SECTION("OpenSim 3 FreeJoint inside its body, with a child location") {
    naming.osim_path = dir.write(
        "f3.osim",
        "<OpenSimDocument Version=\"30000\"><Model><BodySet><objects><Body name=\"block\"><Joint>"
        "<FreeJoint name=\"blockToGround\"><parent_body>ground</parent_body>"
        "<location_in_parent>0 0 0</location_in_parent><orientation_in_parent>0 0 0</orientation_in_parent>"
        "<location>0 0.5 0</location><orientation>0 0 0</orientation>"
        "<CoordinateSet><objects><Coordinate name=\"c0\"/><Coordinate name=\"c1\"/><Coordinate name=\"c2\"/>"
        "<Coordinate name=\"c3\"/><Coordinate name=\"c4\"/><Coordinate "
        "name=\"c5\"/></objects></CoordinateSet>"
        "</FreeJoint></Joint></Body></objects></BodySet></Model></OpenSimDocument>");
    const auto t = read_mot(p, naming);
    CHECK(t.orientation[0].toRotationMatrix().isApprox(xyz, 1e-12));
    // The body origin sits 0.5 m along the body's -y from the joint's child frame.
    CHECK(t.position_m[0].isApprox(Eigen::Vector3d(1, 2, 3) - xyz * Eigen::Vector3d(0, 0.5, 0), 1e-12));
  }
}

TEST_CASE("--osim --joint refuses what is not a free body", "[readers][mot][naming][osim][bad]") {
  ScratchDir dir;
  const auto p = dir.write("ik.mot", sto(kPelvisColumns, kPelvisRow, "inDegrees=yes\n"));
  PoseNaming naming;
  naming.joint = "ground_pelvis";
  SECTION("no such joint") {
    naming.osim_path = dir.write("m.osim", osim4(pelvis_joint()));
    naming.joint = "hip_r";
    CHECK_ONE_LINE_ERROR(read_mot(p, naming), naming.osim_path, "no joint named 'hip_r'", "ground_pelvis");
  }
  SECTION("a pin joint") {
    naming.osim_path = dir.write("pin.osim", osim4("<PinJoint name=\"ground_pelvis\"/>"));
    CHECK_ONE_LINE_ERROR(read_mot(p, naming), naming.osim_path, "PinJoint");
  }
  SECTION("a joint on another body") {
    naming.osim_path = dir.write("b.osim", osim4(pelvis_joint("", "/bodyset/torso")));
    CHECK_ONE_LINE_ERROR(read_mot(p, naming), naming.osim_path, "not ground");
  }
  SECTION("a spline") {
    std::string joint = pelvis_joint();
    const std::string linear =
        "<LinearFunction name=\"function\"><coefficients> 1 0</coefficients></LinearFunction>";
    joint.replace(joint.find(linear), linear.size(),
                  "<SimmSpline name=\"function\"><x>0 1</x><y>0 1</y></SimmSpline>");
    naming.osim_path = dir.write("s.osim", osim4(joint));
    CHECK_ONE_LINE_ERROR(read_mot(p, naming), naming.osim_path, "SimmSpline");
  }
  SECTION("not XML") {
    naming.osim_path = dir.write("x.osim", "<OpenSimDocument><Model>");
    CHECK_ONE_LINE_ERROR(read_mot(p, naming), naming.osim_path, "not a readable OpenSim model");
  }
  SECTION("--osim without --joint") {
    naming.osim_path = dir.write("m.osim", osim4(pelvis_joint()));
    naming.joint.clear();
    CHECK_ONE_LINE_ERROR(read_mot(p, naming), "--joint");
  }
}
