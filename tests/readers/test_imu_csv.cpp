#include <cmath>

#include <catch2/catch.hpp>

#include "one_line_error.hpp"
#include "readers/imu_csv_reader.hpp"
#include "readers/imu_window.hpp"
#include "readers/segments.hpp"
#include "scratch_files.hpp"

using aloft::host::read_imu_csv;
using aloft::test::ScratchDir;

TEST_CASE("plain IMU CSV: gyro only and with accelerometer", "[readers][imu]") {
  ScratchDir dir;
  const auto gyro = read_imu_csv(dir.write("g.csv", "t,gx,gy,gz\n0,1,2,3\n0.001,4,5,6\n"));
  CHECK(gyro.format == "imu_csv");
  REQUIRE(gyro.time_s.size() == 2);
  CHECK(gyro.time_s[1] == 0.001);
  CHECK(gyro.gyro_rad_s[1].isApprox(Eigen::Vector3d(4, 5, 6)));
  CHECK(gyro.accel_m_s2.empty());

  // Columns are found by name, in any order, with spaces around cells.
  const auto both =
      read_imu_csv(dir.write("ga.csv", "gz, gy, gx, t, az, ay, ax\r\n3, 2, 1, 0.5, 9.8, 0, 0.1\r\n"));
  REQUIRE(both.time_s.size() == 1);
  CHECK(both.time_s[0] == 0.5);
  CHECK(both.gyro_rad_s[0].isApprox(Eigen::Vector3d(1, 2, 3)));
  REQUIRE(both.accel_m_s2.size() == 1);
  CHECK(both.accel_m_s2[0].isApprox(Eigen::Vector3d(0.1, 0, 9.8)));
}

TEST_CASE("plain IMU CSV: the rotor's speed in rotor_rad_s", "[readers][imu][rotor]") {
  ScratchDir dir;
  // Any column order, any case; rad/s as written (the gyro's units do not apply to it).
  const auto log = read_imu_csv(
      dir.write("r.csv", "t,gx,gy,gz,Rotor_Rad_S,ax,ay,az\n0,1,2,3,0,0,0,9.8\n0.001,1,2,3,-412.5,0,0,9.8\n"));
  REQUIRE(log.rotor_rad_s.size() == 2);
  CHECK(log.rotor_rad_s[0] == 0.0);
  CHECK(log.rotor_rad_s[1] == -412.5);
  CHECK(log.accel_m_s2.size() == 2);
  // Without the column, none; with a gyro-only log, the column alone.
  CHECK(read_imu_csv(dir.write("n.csv", "t,gx,gy,gz\n0,1,2,3\n")).rotor_rad_s.empty());
  const auto gyro_only = read_imu_csv(dir.write("g.csv", "rotor_rad_s,t,gx,gy,gz\n700,0,1,2,3\n"));
  REQUIRE(gyro_only.rotor_rad_s.size() == 1);
  CHECK(gyro_only.rotor_rad_s[0] == 700.0);
  CHECK(gyro_only.gyro_rad_s[0].isApprox(Eigen::Vector3d(1, 2, 3)));
}

TEST_CASE("phyphox export is recognised by its header", "[readers][imu]") {
  ScratchDir dir;
  const auto log = read_imu_csv(
      dir.write("p.csv",
                "\"Time (s)\",\"Gyroscope x (rad/s)\",\"Gyroscope y (rad/s)\",\"Gyroscope z (rad/s)\","
                "\"Absolute (rad/s)\"\n"
                "6.394458331E-3,-1.361911744E-1,2.411512472E-2,-1.801915616E-1,2.271531952E-1\n"
                "1.641445833E-2,-1.343524158E-1,1.744828187E-2,-1.812447757E-1,2.262845175E-1\n"));
  CHECK(log.format == "phyphox");
  REQUIRE(log.time_s.size() == 2);
  CHECK(log.time_s[0] == 6.394458331e-3);
  CHECK(log.gyro_rad_s[0].x() == -1.361911744e-1);
  CHECK(log.gyro_rad_s[1].z() == -1.812447757e-1);
}

TEST_CASE("real and practice IMU logs read", "[readers][imu][shared]") {
  ALOFT_REQUIRE_SHARED_DATA(data);
  const auto racquet = read_imu_csv(data + "/real/racquet/2025-01-16_17-10-11/gyro.csv");
  CHECK(racquet.format == "phyphox");
  CHECK(racquet.time_s.size() == 5459);  // 5460 lines (the last unterminated) minus the header
  CHECK(racquet.time_s.front() == Approx(6.394458331e-3));
  const auto practice = read_imu_csv(data + "/practice/case00/imu.csv");
  CHECK(practice.format == "imu_csv");
  CHECK(practice.time_s.size() > 100);
  CHECK(practice.time_s[1] - practice.time_s[0] == Approx(0.001));
}

TEST_CASE("bad IMU logs: one-line errors naming file, line and problem", "[readers][imu][bad]") {
  ScratchDir dir;
  SECTION("empty file") {
    const auto p = dir.write("empty.csv", "");
    CHECK_ONE_LINE_ERROR(read_imu_csv(p), p, "empty");
  }
  SECTION("missing file") {
    const auto p = dir.path("nope.csv");
    CHECK_ONE_LINE_ERROR(read_imu_csv(p), p, "cannot open");
  }
  SECTION("wrong header") {
    const auto p = dir.write("h.csv", "time,wx,wy,wz\n0,1,2,3\n");
    CHECK_ONE_LINE_ERROR(read_imu_csv(p), p + ":1:", "header");
  }
  SECTION("header only") {
    const auto p = dir.write("h.csv", "t,gx,gy,gz\n");
    CHECK_ONE_LINE_ERROR(read_imu_csv(p), p, "no samples");
  }
  SECTION("half an accelerometer") {
    const auto p = dir.write("h.csv", "t,gx,gy,gz,ax\n0,1,2,3,4\n");
    CHECK_ONE_LINE_ERROR(read_imu_csv(p), p + ":1:", "accelerometer");
  }
  SECTION("truncated last row") {
    const auto p = dir.write("t.csv", "t,gx,gy,gz\n0,1,2,3\n0.001,1,2");
    CHECK_ONE_LINE_ERROR(read_imu_csv(p), p + ":3:", "truncated");
  }
  SECTION("not a number") {
    const auto p = dir.write("n.csv", "t,gx,gy,gz\n0,1,2,3\n0.001,1,x2,3\n");
    CHECK_ONE_LINE_ERROR(read_imu_csv(p), p + ":3:", "gy", "'x2' is not a number");
  }
  SECTION("empty cell") {
    const auto p = dir.write("n.csv", "t,gx,gy,gz\n0,1,,3\n");
    CHECK_ONE_LINE_ERROR(read_imu_csv(p), p + ":2:", "gy", "empty cell");
  }
  SECTION("NaN value") {
    const auto p = dir.write("n.csv", "t,gx,gy,gz\n0,1,2,3\n0.001,NaN,2,3\n");
    CHECK_ONE_LINE_ERROR(read_imu_csv(p), p + ":3:", "gx", "not finite");
  }
  SECTION("a rotor speed that is not a finite number: as any other cell") {
    for (const char* cell : {"NaN", "inf", "-Infinity"}) {
      INFO(cell);
      const auto p =
          dir.write("r.csv", std::string("t,gx,gy,gz,rotor_rad_s\n0,1,2,3,10\n0.001,1,2,3,") + cell + "\n");
      CHECK_ONE_LINE_ERROR(read_imu_csv(p), p + ":3:", "rotor_rad_s", "not finite");
    }
    const auto empty = dir.write("e.csv", "t,gx,gy,gz,rotor_rad_s\n0,1,2,3,\n");
    CHECK_ONE_LINE_ERROR(read_imu_csv(empty), empty + ":2:", "rotor_rad_s", "empty cell");
    const auto text = dir.write("x.csv", "t,gx,gy,gz,rotor_rad_s\n0,1,2,3,fast\n");
    CHECK_ONE_LINE_ERROR(read_imu_csv(text), text + ":2:", "rotor_rad_s", "'fast' is not a number");
  }
  SECTION("duplicated time stamp") {
    const auto p = dir.write("d.csv", "t,gx,gy,gz\n0,1,2,3\n0.001,1,2,3\n0.001,1,2,3\n");
    CHECK_ONE_LINE_ERROR(read_imu_csv(p), p + ":4:", "repeats");
  }
  SECTION("time going back") {
    const auto p = dir.write("b.csv", "t,gx,gy,gz\n0,1,2,3\n0.002,1,2,3\n0.001,1,2,3\n");
    CHECK_ONE_LINE_ERROR(read_imu_csv(p), p + ":4:", "goes back");
  }
  SECTION("unterminated quote") {
    const auto p = dir.write("q.csv", "\"Time (s),\"Gyroscope x (rad/s)\"\n");
    CHECK_ONE_LINE_ERROR(read_imu_csv(p), p + ":1:");
  }
  SECTION("binary file") {
    const auto p = dir.write("b.csv", std::string("\x02\x50\0\0", 4));
    CHECK_ONE_LINE_ERROR(read_imu_csv(p), p, "binary");
  }
}

TEST_CASE("a window of an IMU log: the samples inside, or an empty-flight error", "[readers][imu]") {
  ScratchDir dir;
  const auto log = read_imu_csv(dir.write(
      "w.csv", "t,gx,gy,gz,ax,ay,az\n0,0,0,0,0,0,0\n1,1,0,0,1,0,0\n2,2,0,0,2,0,0\n3,3,0,0,3,0,0\n"));
  const auto window = aloft::host::imu_window(log, 1.0, 2.5, "segment a");
  REQUIRE(window.time_s == std::vector<double>{1.0, 2.0});
  CHECK(window.gyro_rad_s[1].x() == 2.0);
  CHECK(window.accel_m_s2[0].x() == 1.0);
  CHECK_ONE_LINE_ERROR(aloft::host::imu_window(log, 2.5, 2.9, "segment b"), log.path, "segment b",
                       "holds 0 samples", "the log spans 0–3 s");
  CHECK_ONE_LINE_ERROR(aloft::host::imu_window(log, 5, 9, "segment c"), "holds 0 samples");
}

TEST_CASE("every racquet flight lies inside its session's log", "[readers][imu][shared]") {
  ALOFT_REQUIRE_SHARED_DATA(data);
  for (const char* session : {"2025-01-16_17-10-11", "2025-01-23_18-29-01"}) {
    const std::string folder = data + "/real/racquet/" + session;
    const auto log = read_imu_csv(folder + "/gyro.csv");
    for (const auto& segment : aloft::host::read_segments_csv(folder + "/segments.csv")) {
      INFO(session << " segment " << segment.name);
      const auto flight =
          aloft::host::imu_window(log, segment.start_s, segment.end_s, "segment " + segment.name);
      // About 100 Hz over about a second.
      CHECK(flight.time_s.size() > 70);
      CHECK(flight.time_s.size() < 150);
    }
  }
}
