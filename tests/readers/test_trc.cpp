#include <cmath>

#include <catch2/catch.hpp>

#include "common/warning.hpp"
#include "one_line_error.hpp"
#include "readers/length_units.hpp"
#include "readers/trc_reader.hpp"
#include "scratch_files.hpp"

using aloft::host::read_trc;
using aloft::test::ScratchDir;

namespace {

// A TRC file of two markers; `rows` are the data lines, `units` and NumFrames as given.
std::string trc(const std::string& units, int frames, const std::string& rows,
                const std::string& names = "Frame#\tTime\tA\t\t\tB\t\t") {
  return "PathFileType\t4\t(X/Y/Z)\tt.trc\n"
         "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames"
         "\n"
         "100.00\t100.00\t" +
         std::to_string(frames) + "\t2\t" + units + "\t100.00\t1\t" + std::to_string(frames) + "\n" + names +
         "\n"
         "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\n"
         "\n" +
         rows;
}

const std::string kTwoRows =
    "1\t0.00\t1.0\t2.0\t3.0\t4.0\t5.0\t6.0\n"
    "2\t0.01\t1.5\t2.5\t3.5\t\t\t\n";  // marker B occluded

}  // namespace

TEST_CASE("TRC: units to metres, empty cells occluded, header fields", "[readers][trc]") {
  ScratchDir dir;
  const auto mm = read_trc(dir.write("mm.trc", trc("mm", 2, kTwoRows)));
  CHECK(mm.format == "trc");
  CHECK(mm.units_in_file == "mm");
  CHECK(mm.rate_hz == 100.0);
  CHECK(mm.marker_names == std::vector<std::string>{"A", "B"});
  REQUIRE(mm.time_s.size() == 2);
  CHECK(mm.time_s[1] == 0.01);
  CHECK(mm.positions_m[0][1].isApprox(Eigen::Vector3d(4e-3, 5e-3, 6e-3)));
  CHECK(mm.positions_m[1][0].isApprox(Eigen::Vector3d(1.5e-3, 2.5e-3, 3.5e-3)));
  CHECK_FALSE(mm.positions_m[1][1].allFinite());

  const auto m = read_trc(dir.write("m.trc", trc("m", 2, kTwoRows)));
  CHECK(m.positions_m[0][1].isApprox(Eigen::Vector3d(4, 5, 6)));
  // Some writers mark an occluded marker with NaN rather than empty cells.
  const auto nan_row =
      read_trc(dir.write("n.trc", trc("mm", 2, "1\t0\t1\t2\t3\tNaN\tNaN\tNaN\n2\t0.01\t1\t2\t3\t4\t5\t6\n")));
  CHECK_FALSE(nan_row.positions_m[0][1].allFinite());
}

TEST_CASE("practice marker trials read", "[readers][trc][shared]") {
  ALOFT_REQUIRE_SHARED_DATA(data);
  const auto trial = read_trc(data + "/practice/case10/markers.trc");
  CHECK(trial.rate_hz == 250.0);
  CHECK(trial.time_s.size() == 262);
  CHECK(trial.marker_names == std::vector<std::string>{"M1", "M2", "M3", "M4", "M5", "M6"});
  CHECK(trial.positions_m[0][0].x() == Approx(-76.5692e-3));
  CHECK(trial.positions_m[0][0].y() == Approx(1053.3048e-3));
}

TEST_CASE("bad TRC files: one-line errors", "[readers][trc][bad]") {
  ScratchDir dir;
  SECTION("empty") {
    const auto p = dir.write("e.trc", "");
    CHECK_ONE_LINE_ERROR(read_trc(p), p, "empty");
  }
  SECTION("not a TRC") {
    const auto p = dir.write("x.trc", "t,gx,gy,gz\n0,1,2,3\n");
    CHECK_ONE_LINE_ERROR(read_trc(p), p + ":1:", "PathFileType");
  }
  SECTION("header cut short") {
    const auto p = dir.write("h.trc", "PathFileType\t4\t(X/Y/Z)\tt.trc\nDataRate\tNumFrames\n");
    CHECK_ONE_LINE_ERROR(read_trc(p), p, "header");
  }
  SECTION("unknown units") {
    const auto p = dir.write("u.trc", trc("furlongs", 2, kTwoRows));
    CHECK_ONE_LINE_ERROR(read_trc(p), p + ":3:", "unknown units 'furlongs'");
  }
  SECTION("marker names disagree with NumMarkers") {
    const auto p = dir.write("n.trc", trc("mm", 2, kTwoRows, "Frame#\tTime\tA\t\t\t\t\t"));
    CHECK_ONE_LINE_ERROR(read_trc(p), p + ":4:", "NumMarkers");
  }
  SECTION("truncated in a row") {
    const auto p =
        dir.write("t.trc", trc("mm", 2, "1\t0.00\t1.0\t2.0\t3.0\t4.0\t5.0\t6.0\n2\t0.01\t1.5\t2."));
    CHECK_ONE_LINE_ERROR(read_trc(p), p + ":8:", "truncated");
  }
  SECTION("half a marker") {
    const auto p =
        dir.write("h.trc", trc("mm", 2, "1\t0.00\t1.0\t\t3.0\t4.0\t5.0\t6.0\n2\t0.01\t1\t2\t3\t4\t5\t6\n"));
    CHECK_ONE_LINE_ERROR(read_trc(p), p + ":7:", "marker A", "some of X, Y, Z");
  }
  SECTION("not a number") {
    const auto p = dir.write(
        "x.trc", trc("mm", 2, "1\t0.00\t1.0\t2.0\t3.0\t4.0\tfive\t6.0\n2\t0.01\t1\t2\t3\t4\t5\t6\n"));
    CHECK_ONE_LINE_ERROR(read_trc(p), p + ":7:", "B Y", "'five'");
  }
  SECTION("duplicated time") {
    const auto p = dir.write("d.trc", trc("mm", 2, "1\t0.00\t1\t2\t3\t4\t5\t6\n2\t0.00\t1\t2\t3\t4\t5\t6\n"));
    CHECK_ONE_LINE_ERROR(read_trc(p), p + ":8:", "repeats");
  }
  SECTION("time going back") {
    const auto p = dir.write("b.trc", trc("mm", 2, "1\t0.02\t1\t2\t3\t4\t5\t6\n2\t0.01\t1\t2\t3\t4\t5\t6\n"));
    CHECK_ONE_LINE_ERROR(read_trc(p), p + ":8:", "goes back");
  }
  SECTION("infinite coordinate") {
    const auto p =
        dir.write("i.trc", trc("mm", 2, "1\t0.00\t1\t2\tinf\t4\t5\t6\n2\t0.01\t1\t2\t3\t4\t5\t6\n"));
    CHECK_ONE_LINE_ERROR(read_trc(p), p + ":7:", "A Z", "infinite");
  }
  SECTION("no frames") {
    const auto p = dir.write("z.trc", trc("mm", 0, ""));
    CHECK_ONE_LINE_ERROR(read_trc(p), p, "no frames");
  }
}

TEST_CASE("TRC header cells separated by repeated tabs are read as OpenSim reads them", "[readers][trc]") {
  ScratchDir dir;
  // The Rajagopal pipeline's layout: two tabs between the header cells of lines 2 and 3.
  const std::string doubled =
      "PathFileType\t4\t(X/Y/Z)\tt.trc\n"
      "DataRate\t\tCameraRate\t\tNumFrames\t\tNumMarkers\t\tUnits\n"
      "100\t\t100\t\t2\t\t2\t\tmm\n"
      "Frame#\tTime\tA\t\t\tB\t\t\n"
      "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\n\n" +
      kTwoRows;
  const auto trial = read_trc(dir.write("d.trc", doubled));
  CHECK(trial.rate_hz == 100.0);
  CHECK(trial.units_in_file == "mm");
  REQUIRE(trial.time_s.size() == 2);
  CHECK(trial.positions_m[0][1].isApprox(Eigen::Vector3d(4e-3, 5e-3, 6e-3)));
}

TEST_CASE("TRC whose NumFrames disagrees with its rows: the rows present, with a warning", "[readers][trc]") {
  ScratchDir dir;
  SECTION("NumFrames claims more") {
    aloft::host::WarningCapture warnings;
    const auto p = dir.write("f.trc", trc("mm", 3, kTwoRows));
    const auto trial = read_trc(p);
    CHECK(trial.time_s.size() == 2);
    CHECK(trial.positions_m[1][0].isApprox(Eigen::Vector3d(1.5e-3, 2.5e-3, 3.5e-3)));
    REQUIRE(warnings.messages().size() == 1);
    CHECK(warnings.contains(p));
    CHECK(warnings.contains("2 frames where NumFrames is 3"));
  }
  SECTION("NumFrames claims fewer") {
    aloft::host::WarningCapture warnings;
    const auto trial = read_trc(dir.write("g.trc", trc("mm", 1, kTwoRows)));
    CHECK(trial.time_s.size() == 2);
    CHECK(warnings.contains("2 frames where NumFrames is 1"));
  }
  SECTION("matching counts give no warning") {
    aloft::host::WarningCapture warnings;
    read_trc(dir.write("h.trc", trc("mm", 2, kTwoRows)));
    CHECK(warnings.messages().empty());
  }
  SECTION("a row cut short is still refused") {
    const auto p = dir.write("t.trc", trc("mm", 3, "1\t0.00\t1.0\t2.0\t3.0\t4.0\t5.0\t6.0\n2\t0.01\t1.5"));
    CHECK_ONE_LINE_ERROR(read_trc(p), p + ":8:", "truncated");
  }
}

TEST_CASE("length units are matched trimmed, case-folded and by prefix", "[readers][trc][units]") {
  using aloft::host::metres_per_unit;
  CHECK(metres_per_unit("mm") == 1e-3);
  CHECK(metres_per_unit(" MM ") == 1e-3);
  CHECK(metres_per_unit("millimeters") == 1e-3);
  CHECK(metres_per_unit("Millimetres") == 1e-3);
  CHECK(metres_per_unit("cm") == 1e-2);
  CHECK(metres_per_unit("centimeters") == 1e-2);
  CHECK(metres_per_unit("m") == 1.0);
  CHECK(metres_per_unit("mete") == 1.0);  // Peak Performance's 4-character POINT:UNITS
  CHECK(metres_per_unit("meters") == 1.0);
  CHECK(metres_per_unit("Metres") == 1.0);
  CHECK(metres_per_unit("") == 0.0);
  CHECK(metres_per_unit("in") == 0.0);
  CHECK(metres_per_unit("furlongs") == 0.0);
  CHECK(metres_per_unit("meterstick") == 0.0);
  CHECK(metres_per_unit("mi") == 0.0);  // miles or millimetres: too short to tell
}
