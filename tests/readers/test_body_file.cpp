// The body file reader's boundary: a library's exception never reaches the user, and keys
// SPEC §2 does not know are named in a warning.
#include <catch2/catch.hpp>

#include "common/body_file.hpp"
#include "common/warning.hpp"
#include "one_line_error.hpp"
#include "scratch_files.hpp"

using aloft::host::read_body_file;
using aloft::host::WarningCapture;
using aloft::test::ScratchDir;

TEST_CASE("body file: JSON library errors become one line naming the file", "[readers][body][bad]") {
  ScratchDir dir;
  SECTION("a number out of double's range") {
    const auto p = dir.write("b.json", R"({"mass": 1e400, "inertia": {"principal": [1, 2, 2.5]}})");
    const std::string message = aloft::test::error_message_of([&] { read_body_file(p); });
    CHECK(message.find(p) == 0);
    CHECK(message.find("1e400") != std::string::npos);
    CHECK(message.find("json.exception") == std::string::npos);
  }
  SECTION("broken syntax") {
    const auto p = dir.write("s.json", R"({"mass": 1, )");
    const std::string message = aloft::test::error_message_of([&] { read_body_file(p); });
    CHECK(message.find(p) == 0);
    CHECK(message.find("json.exception") == std::string::npos);
  }
  SECTION("a missing file") {
    CHECK_ONE_LINE_ERROR(read_body_file(dir.path("none.json")), "none.json", "cannot open");
  }
}

TEST_CASE("body file: unknown keys are named in a warning", "[readers][body]") {
  ScratchDir dir;
  SECTION("misspelt keys at several levels") {
    WarningCapture warnings;
    const auto p = dir.write("b.json", R"({"name": "box", "mass": 1, "marker": {},
        "inertia": {"principal": [1, 2, 2.5], "axis": [1, 0, 0, 0]}, "imu": {"rotaton": [1, 0, 0, 0]}})");
    const auto body = read_body_file(p);
    CHECK(body.name == "box");
    CHECK(warnings.messages().size() == 3);  // one line per object that holds unknown keys
    for (const std::string& m : warnings.messages()) CHECK(m.find(p) == 0);
    CHECK(warnings.contains("\"marker\""));
    CHECK(warnings.contains("\"inertia.axis\""));
    CHECK(warnings.contains("\"imu.rotaton\""));
  }
  SECTION("a file of known keys only: no warning") {
    WarningCapture warnings;
    read_body_file(dir.write(
        "k.json",
        R"({"name": "c", "mass": 2, "inertia": {"shape": {"cylinder": {"radius": 0.1, "height": 0.2}}},
        "markers": {"M1": [0, 0, 0.1]}, "imu": {"rotation": [1, 0, 0, 0]}})"));
    CHECK(warnings.messages().empty());
  }
}

TEST_CASE("body file: imu.position is the accelerometer's place in body axes", "[readers][body]") {
  ScratchDir dir;
  const std::string head = R"({"inertia": {"principal": [1, 2, 2.5]}, "imu": )";
  SECTION("given: metres in body axes, as written") {
    const auto body = read_body_file(dir.write("p.json", head + R"({"position": [0.031, -0.004, 0.0125]}})"));
    REQUIRE(body.imu_position_m.has_value());
    CHECK(body.imu_position_m->x() == 0.031);
    CHECK(body.imu_position_m->y() == -0.004);
    CHECK(body.imu_position_m->z() == 0.0125);
  }
  SECTION("given beside a rotation: both are kept, no warning") {
    WarningCapture warnings;
    const auto body =
        read_body_file(dir.write("r.json", head + R"({"rotation": [0, 0, 0, 1], "position": [0, 0, 0]}})"));
    REQUIRE(body.imu_position_m.has_value());
    CHECK(body.imu_position_m->norm() == 0.0);
    CHECK(body.imu_to_body.z() == 1.0);
    CHECK(warnings.messages().empty());
  }
  SECTION("absent: none, so the pipeline estimates it") {
    CHECK_FALSE(read_body_file(dir.write("n.json", head + R"({"rotation": [1, 0, 0, 0]}})")).imu_position_m);
    CHECK_FALSE(
        read_body_file(dir.write("m.json", R"({"inertia": {"principal": [1, 2, 2.5]}})")).imu_position_m);
  }
  SECTION("bad values: one line naming the file and the key") {
    for (const char* bad : {R"([0.01, 0.02])", R"([0.01, 0.02, 0.03, 0.04])", R"("0.01, 0.02, 0.03")",
                            R"([0.01, "y", 0.03])", R"([0.01, null, 0.03])", R"({"x": 0.01})", "0.01"}) {
      INFO("imu.position: " << bad);
      const auto p = dir.write("bad.json", head + R"({"position": )" + bad + "}}");
      CHECK_ONE_LINE_ERROR(read_body_file(p), p, "imu.position");
    }
  }
}
