// Units checked from the physics (issue 26 item 5, "Units, checked and named"): a log in
// the wrong units is refused with one line that names the likely unit and the option
// that converts it, exit 2, instead of a confident wrong answer; and the option makes the
// same log right. Segments outside the log, in ms, or over a rest period are bad input.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <string>

#include "made_up_box.hpp"

using namespace aloft::test;

namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The refusal: exit 2, one line, nothing on stdout, every word of `words` named.
void check_refused(const RunResult& r, const std::vector<std::string>& words) {
  CAPTURE(r.err);
  CHECK(r.exit_code == 2);
  CHECK(count_lines(r.err) == 1);
  CHECK(r.out.empty());
  for (const std::string& w : words) CHECK(has(r.err, w));
}

struct Files {
  ScratchDir dir;
  std::string body = dir.write("box.json", nominal_box_json());
};

}  // namespace

TEST_CASE("a gyro in deg/s is named from Euler's equations, and --gyro-units deg/s reads it",
          "[first_hour]") {
  Files f;
  const std::vector<Sample> flight = made_up_throw(f.dir);
  Units degrees;
  degrees.gyro = kDegreesPerRadian;
  const std::string log = f.dir.write("deg.csv", imu_csv(flight, degrees, false));
  check_refused(run_aloft(f.dir, "diagnose --body " + f.body + " --imu " + log),
                {"deg.csv", "°/s", "57.3", "--gyro-units deg/s"});
  const std::string converted = f.dir.path("converted.json"), plain = f.dir.path("plain.json");
  const RunResult fixed = run_aloft(
      f.dir, "diagnose --body " + f.body + " --imu " + log + " --gyro-units deg/s --json " + converted);
  CAPTURE(fixed.err);
  CHECK(fixed.exit_code == 0);
  // The same log in rad/s diagnoses as the converted one does (to the rounding of the
  // written values).
  const std::string rad = f.dir.write("rad.csv", imu_csv(flight, Units{}, false));
  REQUIRE(run_aloft(f.dir, "diagnose --body " + f.body + " --imu " + rad + " --json " + plain).exit_code ==
          0);
  const nlohmann::json a = nlohmann::json::parse(read_file(converted)),
                       b = nlohmann::json::parse(read_file(plain));
  CHECK(a["verdict"]["effect"] == b["verdict"]["effect"]);
  for (int k = 0; k < 2; ++k) {
    const double ratio = b["tensor"]["ratio_best"][k].get<double>();
    CHECK(a["tensor"]["ratio_best"][k].get<double>() == Approx(ratio).epsilon(1e-3));
  }
}

TEST_CASE("times in ms are named: by the physics in a window, by the clock in a long log", "[first_hour]") {
  Files f;
  Units ms;
  ms.time = 1000.0;
  const std::string log = f.dir.write("ms.csv", imu_csv(made_up_throw(f.dir), ms, false));
  check_refused(run_aloft(f.dir, "diagnose --body " + f.body + " --imu " + log + " --window 0:800"),
                {"ms.csv", "ms", "--time-units ms"});
  check_refused(run_aloft(f.dir, "diagnose --body " + f.body + " --imu " + log),
                {"ms.csv", "--time-units ms"});
}

TEST_CASE("a session in ms with an accelerometer: the flights found are refused by the physics",
          "[first_hour]") {
  Files f;
  Units ms;
  ms.time = 1000.0;
  const std::string log = f.dir.write("ms.csv", imu_csv(made_up_session(f.dir).samples, ms, true));
  check_refused(run_aloft(f.dir, "diagnose --body " + f.body + " --imu " + log),
                {"ms.csv", "--time-units ms"});
}

TEST_CASE("an accelerometer in g is named from its reading at rest", "[first_hour]") {
  Files f;
  Units g;
  g.accel = 1.0 / kGravity;
  const Session session = made_up_session(f.dir);
  const std::string log = f.dir.write("g.csv", imu_csv(session.samples, g, true));
  check_refused(run_aloft(f.dir, "diagnose --body " + f.body + " --imu " + log),
                {"g.csv", "1.00", "--accel-units g"});
  check_refused(run_aloft(f.dir, "replay --body " + f.body + " --imu " + log), {"g.csv", "--accel-units g"});
  // Converted, the replay's flight detector finds the three throws: a row each, and a line
  // each under the tensor estimate's heading, below 4 lines: the stream, the gyro filter,
  // the table's heading and the tensor estimate's.
  const RunResult fixed = run_aloft(f.dir, "replay --body " + f.body + " --imu " + log + " --accel-units g");
  CAPTURE(fixed.err);
  CHECK(fixed.exit_code == 0);
  CHECK(count_lines(fixed.out) == 4 + 2 * session.flights.size());
  const RunResult inspected = run_aloft(f.dir, "inspect " + log);
  CHECK(has(inspected.out, "in g (--accel-units g)"));
}

TEST_CASE("segments outside the log, in ms, or over a rest period are refused by name", "[first_hour]") {
  Files f;
  const Session session = made_up_session(f.dir);
  const std::string log = f.dir.write("imu.csv", imu_csv(session.samples, Units{}, true));
  const std::string in_ms = f.dir.write("ms.csv", segments_csv(session, 1000.0));
  check_refused(run_aloft(f.dir, "diagnose --body " + f.body + " --imu " + log + " --segments " + in_ms),
                {"ms.csv", "segment throw1", "not inside the log", "milliseconds"});
  const std::string outside = f.dir.write("late.csv", "segment,start,end\nthrow1,1.0,1.8\nlate,20,21\n");
  check_refused(run_aloft(f.dir, "diagnose --body " + f.body + " --imu " + log + " --segments " + outside),
                {"late.csv", "segment late", "not inside the log"});
  const std::string rest = f.dir.write("rest.csv", "segment,start,end\ntable,0.1,0.9\n");
  check_refused(run_aloft(f.dir, "diagnose --body " + f.body + " --imu " + log + " --segments " + rest),
                {"rest.csv", "segment table", "rest period"});
  check_refused(run_aloft(f.dir, "diagnose --body " + f.body + " --imu " + log + " --window 30:31"),
                {"--window", "not inside the log"});
}

TEST_CASE(
    "study --imu reads a log in deg/s and ms with the unit options, as it reads the SI log, and "
    "refuses it without them",
    "[first_hour]") {
  Files f;
  const std::vector<Sample> flight = made_up_throw(f.dir);
  Units other;
  other.gyro = kDegreesPerRadian;
  other.time = 1000.0;
  const std::string converted_log = f.dir.write("deg_ms.csv", imu_csv(flight, other, false));
  const std::string si_log = f.dir.write("si.csv", imu_csv(flight, Units{}, false));
  auto study = [&](const std::string& log, const std::string& options, const std::string& out) {
    const RunResult r = run_aloft(f.dir, "study --body " + f.body + " --imu " + log + options +
                                             " --mc-samples 20 --threads 1 --out " + f.dir.path(out));
    CAPTURE(r.err);
    REQUIRE(r.exit_code == 0);
    return nlohmann::json::parse(read_file(f.dir.path(out) + "/results.json"));
  };
  const nlohmann::json si = study(si_log, "", "si");
  const nlohmann::json converted = study(converted_log, " --gyro-units deg/s --time-units ms", "converted");
  // The nominal tensor's RMS DA on the flight: equal to the rounding of the written values.
  const double nominal = si["models"]["nominal"]["rms_da_deg"]["median"].get<double>();
  CHECK(nominal < 5.0);
  CHECK(converted["models"]["nominal"]["rms_da_deg"]["median"].get<double>() ==
        Approx(nominal).epsilon(1e-3));
  // Without the options the log is refused as diagnose refuses it, from Euler's
  // equations, with the options named (its simulations, 1000 s long at 57 times the rate,
  // once gave a null median instead).
  check_refused(run_aloft(f.dir, "study --body " + f.body + " --imu " + converted_log +
                                     " --mc-samples 20 --threads 1 --out " + f.dir.path("unconverted")),
                {"deg_ms.csv", "°/s", "ms", "--gyro-units deg/s --time-units ms"});
}
