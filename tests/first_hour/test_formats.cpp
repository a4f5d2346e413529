// Formats a new user's files come in (issue 26 item 5, "Formats"): a UTF-8 byte order
// mark, tab-separated logs and phyphox's semicolon and tab exports are read, each to the
// same samples as the plain CSV; a body file's tensor written as three numbers is
// refused with what is wanted; a tensor in g·cm² is named from the body's mass and size;
// where quaternions are read, their order (w first) is named beside scipy's (w last).
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <string>

#include "made_up_box.hpp"

using namespace aloft::test;

namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// phyphox's gyroscope export, its header quoted, in one of its delimiter and decimal
// settings.
std::string phyphox(const std::vector<Sample>& samples, char delimiter, char decimal) {
  std::string text;
  for (const char* name : {"Time (s)", "Gyroscope x (rad/s)", "Gyroscope y (rad/s)", "Gyroscope z (rad/s)"}) {
    text += (text.empty() ? "\"" : std::string(1, delimiter) + "\"") + name + "\"";
  }
  text += "\n";
  char cell[40];
  for (const Sample& s : samples) {
    const double values[4] = {s.t, s.gyro[0], s.gyro[1], s.gyro[2]};
    for (int k = 0; k < 4; ++k) {
      std::snprintf(cell, sizeof cell, "%.9E", values[k]);
      std::string c = cell;
      if (decimal == ',') c[c.find('.')] = ',';
      text += (k ? std::string(1, delimiter) : "") + c;
    }
    text += "\n";
  }
  return text;
}

nlohmann::json inspect(const ScratchDir& dir, const std::string& file) {
  const RunResult r = run_aloft(dir, "inspect " + file);
  CAPTURE(r.err);
  REQUIRE(r.exit_code == 0);
  return nlohmann::json::parse(r.out);
}

}  // namespace

TEST_CASE("a byte order mark, tabs, and phyphox's other exports read to the same log", "[first_hour]") {
  ScratchDir dir;
  const std::vector<Sample> flight = made_up_throw(dir);
  const std::string plain = imu_csv(flight, Units{}, false);
  std::string tabbed = plain;
  for (char& c : tabbed) c = c == ',' ? '\t' : c;
  const nlohmann::json reference = inspect(dir, dir.write("plain.csv", plain));
  const std::vector<std::pair<std::string, std::string>> variants = {
      {"bom.csv", "\xEF\xBB\xBF" + plain},
      {"tabs.csv", tabbed},
      {"phyphox_comma.csv", phyphox(flight, ',', '.')},
      {"phyphox_semicolon.csv", phyphox(flight, ';', '.')},
      {"phyphox_tab.csv", phyphox(flight, '\t', '.')},
      {"phyphox_semicolon_decimal_comma.csv", phyphox(flight, ';', ',')},
      {"phyphox_tab_decimal_comma.csv", "\xEF\xBB\xBF" + phyphox(flight, '\t', ',')},
  };
  for (const auto& [name, text] : variants) {
    CAPTURE(name);
    const nlohmann::json j = inspect(dir, dir.write(name, text));
    CHECK(j["frames"] == reference["frames"]);
    CHECK(j["duration_s"].get<double>() == Approx(reference["duration_s"].get<double>()));
    CHECK(j["max_gyro_rad_s"].get<double>() ==
          Approx(reference["max_gyro_rad_s"].get<double>()).epsilon(1e-6));
  }
}

TEST_CASE("a tensor of three numbers is refused with what is wanted", "[first_hour]") {
  ScratchDir dir;
  const std::string body =
      dir.write("b.json", R"({"mass": 1, "inertia": {"tensor": [0.004, 0.008, 0.011]}})");
  const RunResult r = run_aloft(
      dir, "simulate --body " + body + " --w0 1,2,3 --duration 0.1 --rate 100 --out " + dir.path("t.csv"));
  CAPTURE(r.err);
  CHECK(r.exit_code == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK(has(r.err, "3x3 array"));
  CHECK(has(r.err, "\"principal\": [I1, I2, I3]"));
}

TEST_CASE("a tensor in g·cm² is named from the body's mass and size", "[first_hour]") {
  ScratchDir dir;
  // The box's moments in g·cm²: 10^7 times kg·m².
  const std::string grams =
      dir.write("g_cm2.json", R"({"mass": 1, "inertia": {"principal": [41666.7, 83333.3, 108333.3]}})");
  const RunResult r = run_aloft(
      dir, "simulate --body " + grams + " --w0 1,2,3 --duration 0.1 --rate 100 --out " + dir.path("t.csv"));
  CAPTURE(r.err);
  CHECK(r.exit_code == 0);
  CHECK(has(r.err, "warning"));
  CHECK(has(r.err, "g·cm²"));
  CHECK(has(r.err, "0.01083 kg·m²"));
  // Markers give the size: the same moments in kg·m² on markers 2 cm out are too large too.
  const std::string small =
      dir.write("small.json", R"({"mass": 1, "inertia": {"principal": [0.004, 0.008, 0.011]},
      "markers": {"a": [0.02, 0, 0], "b": [0, 0.02, 0], "c": [0, 0, 0.02]}})");
  CHECK(has(run_aloft(dir, "simulate --body " + small + " --w0 1,2,3 --duration 0.1 --rate 100 --out " +
                               dir.path("t.csv"))
                .err,
            "farthest marker lies 0.02 m"));
  // The true box's own moments pass without a word.
  const std::string right = dir.write("box.json", nominal_box_json());
  CHECK(!has(run_aloft(dir, "simulate --body " + right + " --w0 1,2,3 --duration 0.1 --rate 100 --out " +
                                dir.path("t.csv"))
                 .err,
             "warning"));
}

TEST_CASE("where quaternions are read, their order is named beside scipy's", "[first_hour]") {
  ScratchDir dir;
  const std::string poses = dir.write("poses.csv", "t,qw,qx,qy,qz\n0,1,0,0,0\n0.01,1,0,0,0\n0.02,1,0,0,0\n");
  CHECK(has(inspect(dir, poses)["quaternion_order"].get<std::string>(), "scipy"));
  const std::string body = dir.write("b.json", R"({"mass": 1, "inertia": {"principal": [1, 2, 2.5]},
      "imu": {"rotation": [0, 0, 1]}})");
  const RunResult r = run_aloft(
      dir, "simulate --body " + body + " --w0 1,2,3 --duration 0.1 --rate 100 --out " + dir.path("t.csv"));
  CHECK(r.exit_code == 2);
  CHECK(has(r.err, "[w, x, y, z]"));
  CHECK(has(r.err, "scipy"));
  CHECK(has(run_aloft(dir, "simulate --help").out, "scipy"));
}
