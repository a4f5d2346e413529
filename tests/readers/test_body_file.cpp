// The body file reader's boundary: a library's exception never reaches the user, and keys
// SPEC §2 does not know are named in a warning; a rotor is read whole or refused.
#include <catch2/catch.hpp>

#include <cmath>
#include <utility>

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

TEST_CASE("body file: rotor is a wheel's moment and its spin axis in body axes", "[readers][body]") {
  ScratchDir dir;
  const std::string head = R"({"inertia": {"principal": [0.002, 0.003, 0.004]}, "rotor": )";
  SECTION("given: the moment as written, the axis normalised") {
    WarningCapture warnings;
    const auto body =
        read_body_file(dir.write("r.json", head + R"({"inertia_kg_m2": 1.5e-5, "axis": [0, 3, 4]}})"));
    REQUIRE(body.rotor.has_value());
    CHECK(body.rotor->inertia_kg_m2 == 1.5e-5);
    CHECK(body.rotor->axis.x() == 0.0);
    CHECK(body.rotor->axis.y() == Approx(0.6).epsilon(1e-15));
    CHECK(body.rotor->axis.z() == Approx(0.8).epsilon(1e-15));
    CHECK(warnings.messages().empty());
  }
  SECTION("an axis of any length is a direction: tiny and huge components") {
    const auto tiny =
        read_body_file(dir.write("t.json", head + R"({"inertia_kg_m2": 1e-5, "axis": [1e-200, 0, 0]}})"));
    CHECK(tiny.rotor->axis.x() == 1.0);
    const auto huge =
        read_body_file(dir.write("h.json", head + R"({"inertia_kg_m2": 1e-5, "axis": [1e300, -1e300, 0]}})"));
    CHECK(huge.rotor->axis.x() == Approx(std::sqrt(0.5)).epsilon(1e-15));
    CHECK(huge.rotor->axis.y() == Approx(-std::sqrt(0.5)).epsilon(1e-15));
  }
  SECTION("absent: none") {
    CHECK_FALSE(read_body_file(dir.write("n.json", R"({"inertia": {"principal": [1, 2, 2.5]}})")).rotor);
  }
  SECTION("bad rotors: one line naming the file and the key") {
    const std::pair<const char*, const char*> bad[] = {
        {R"({"inertia_kg_m2": 0, "axis": [0, 0, 1]})", "positive"},
        {R"({"inertia_kg_m2": -1e-5, "axis": [0, 0, 1]})", "positive"},
        {R"({"inertia_kg_m2": 1e400, "axis": [0, 0, 1]})", "1e400"},
        {R"({"inertia_kg_m2": "1e-5", "axis": [0, 0, 1]})", "rotor.inertia_kg_m2"},
        {R"({"inertia_kg_m2": null, "axis": [0, 0, 1]})", "rotor.inertia_kg_m2"},
        {R"({"axis": [0, 0, 1]})", "missing \"rotor.inertia_kg_m2\""},
        {R"({"inertia_kg_m2": 1e-5})", "missing \"rotor.axis\""},
        {R"({"inertia_kg_m2": 1e-5, "axis": [0, 0, 0]})", "rotor.axis"},
        {R"({"inertia_kg_m2": 1e-5, "axis": [0, 0]})", "rotor.axis"},
        {R"({"inertia_kg_m2": 1e-5, "axis": [0, "z", 1]})", "rotor.axis"},
        {R"({"inertia_kg_m2": 1e-5, "axis": [0, 0, 1], "speed_rad_s": 100})", "\"rotor.speed_rad_s\""},
        {R"({"inertia": 1e-5, "axis": [0, 0, 1]})", "\"rotor.inertia\""},
        {R"([1e-5, 0, 0, 1])", "\"rotor\" must be an object"},
        // The assembly includes the rotor: 0.004 about z is the whole body's.
        {R"({"inertia_kg_m2": 0.004, "axis": [0, 0, 1]})", "whole body's moment"},
        {R"({"inertia_kg_m2": 15, "axis": [1, 0, 0]})", "whole body's moment"},
    };
    for (const auto& [rotor, fragment] : bad) {
      INFO("rotor: " << rotor);
      const auto p = dir.write("bad.json", head + rotor + "}");
      CHECK_ONE_LINE_ERROR(read_body_file(p), p, fragment);
    }
  }
}
