// Bad and awkward input for `aloft diagnose`: one-line errors and no report for what
// cannot be read or judged; a report that says what it could not judge, never a confident
// wrong verdict, for flights with gaps or a saturated gyro.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "common/commands.hpp"
#include "diagnose/5_flow/diagnosis.hpp"
#include "diagnose/1_input/flight_input.hpp"
#include "generator/flight_generator.hpp"

namespace fs = std::filesystem;
using namespace aloft::host;
using namespace aloft::host::diagnose;

namespace {

// A scratch folder removed at the end of the test.
struct Scratch {
  fs::path dir;
  Scratch() {
    dir = fs::temp_directory_path() /
          ("aloft_diagnose_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter()++));
    fs::create_directories(dir);
  }
  ~Scratch() { fs::remove_all(dir); }
  static int& counter() {
    static int n = 0;
    return n;
  }
  std::string file(const std::string& name) const { return (dir / name).string(); }
};

void write_imu(const std::string& path, const ImuLog& log) {
  std::ofstream out(path);
  out << "t,gx,gy,gz\n";
  char line[160];
  for (std::size_t k = 0; k < log.time_s.size(); ++k) {
    std::snprintf(line, sizeof line, "%.6f,%.9g,%.9g,%.9g\n", log.time_s[k], log.gyro_rad_s[k].x(),
                  log.gyro_rad_s[k].y(), log.gyro_rad_s[k].z());
    out << line;
  }
}

aloft::generator::GeneratedFlight noise_only_flight(std::uint64_t seed) {
  aloft::generator::FlightSpec spec;
  spec.body = "box";
  spec.effect = "none";
  spec.duration_s = 1.0;
  return aloft::generator::generate_flight(spec, seed);
}

// Runs `aloft diagnose ARGS`; returns the error message ("" when it succeeded).
std::string run(std::vector<std::string> args) {
  CLI::App app;
  add_diagnose_command(app);
  args.insert(args.begin(), "diagnose");
  std::vector<const char*> argv = {"aloft"};
  for (const auto& a : args) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const Error& e) {
    return e.what();
  } catch (const CLI::ParseError& e) {
    return std::string("usage: ") + e.what();
  }
  return "";
}

bool one_line(const std::string& s) { return !s.empty() && s.find('\n') == std::string::npos; }

}  // namespace

TEST_CASE("diagnose refuses bad arguments with one line and writes no report", "[diagnose][bad]") {
  Scratch scratch;
  const auto g = noise_only_flight(11);
  std::ofstream(scratch.file("body.json")) << g.body_json;
  write_imu(scratch.file("imu.csv"), g.imu);
  const std::string body = scratch.file("body.json"), imu = scratch.file("imu.csv");
  const std::string report = scratch.file("report.json");

  SECTION("no trial") { CHECK(one_line(run({"--body", body, "--json", report}))); }
  SECTION("two trials") {
    CHECK(one_line(run({"--body", body, "--imu", imu, "--poses", imu, "--json", report})));
  }
  SECTION("--window without A:B") {
    const std::string e = run({"--body", body, "--imu", imu, "--window", "0.5", "--json", report});
    CHECK(one_line(e));
    CHECK(e.find("--window") != std::string::npos);
  }
  SECTION("a long log without an accelerometer, --segments or --window") {
    ImuLog long_log;
    for (int k = 0; k < 700; ++k) {
      long_log.time_s.push_back(0.01 * k);
      long_log.gyro_rad_s.push_back(Eigen::Vector3d(0.1, 0.0, 0.0));
    }
    write_imu(scratch.file("long.csv"), long_log);
    const std::string e = run({"--body", body, "--imu", scratch.file("long.csv"), "--json", report});
    CHECK(one_line(e));
    CHECK(e.find("--segments") != std::string::npos);
    CHECK(e.find("--window") != std::string::npos);
    CHECK_FALSE(fs::exists(report));
  }
  SECTION("--window backwards") {
    CHECK(one_line(run({"--body", body, "--imu", imu, "--window", "0.8:0.2", "--json", report})));
  }
  SECTION("--segments with --poses") {
    CHECK(one_line(run({"--body", body, "--poses", imu, "--segments", imu, "--json", report})));
  }
  SECTION("missing body file names it") {
    const std::string e = run({"--body", scratch.file("nope.json"), "--imu", imu, "--json", report});
    CHECK(one_line(e));
    CHECK(e.find("nope.json") != std::string::npos);
  }
  SECTION("a truncated IMU log names the file") {
    std::ofstream(scratch.file("bad.csv")) << "t,gx,gy,gz\n0.0,1,2,3\n0.001,1,2\n";
    const std::string e = run({"--body", body, "--imu", scratch.file("bad.csv"), "--json", report});
    CHECK(one_line(e));
    CHECK(e.find("bad.csv") != std::string::npos);
  }
  SECTION("fewer than 20 samples") {
    const std::string e = run({"--body", body, "--imu", imu, "--window", "0.1:0.110", "--json", report});
    CHECK(one_line(e));
    CHECK(e.find("samples") != std::string::npos);
  }
  CHECK_FALSE(fs::exists(report));
}

TEST_CASE("diagnose writes the report of a good flight", "[diagnose]") {
  Scratch scratch;
  const auto g = noise_only_flight(12);
  std::ofstream(scratch.file("body.json")) << g.body_json;
  write_imu(scratch.file("imu.csv"), g.imu);
  const std::string report = scratch.file("report.json");
  CHECK(run({"--body", scratch.file("body.json"), "--imu", scratch.file("imu.csv"), "--window", "0.0:0.6",
             "--json", report, "--plot", scratch.file("plots")})
            .empty());
  REQUIRE(fs::exists(report));
  nlohmann::json r;
  std::ifstream(report) >> r;
  for (const char* key : {"baseline", "where", "candidates", "verdict"}) CHECK(r.contains(key));
  CHECK(r["verdict"]["effect"] == "none");
  CHECK(r["where"]["onset_s"].is_null());
  CHECK(fs::exists(scratch.file("plots/gap.svg")));
  CHECK(fs::exists(scratch.file("plots/gap.png")));
}

TEST_CASE("a flight with gaps in its time stamps is judged, and the gaps reported", "[diagnose]") {
  auto g = noise_only_flight(13);
  ImuLog log;
  for (std::size_t k = 0; k < g.imu.time_s.size(); ++k) {
    const double t = g.imu.time_s[k];
    if ((t > 0.30 && t < 0.38) || (t > 0.70 && t < 0.72)) continue;  // dropped samples
    log.time_s.push_back(t);
    log.gyro_rad_s.push_back(g.imu.gyro_rad_s[k]);
  }
  Flight flight = flight_from_imu(log, g.body, -INFINITY, INFINITY, "gappy");
  const FlightDiagnosis d = diagnose_flight(flight, NominalInertia::of(g.body.inertia));
  CHECK(d.gaps.size() == 2);
  CHECK(d.analysis.verdict.effect == Effect::none);
}

TEST_CASE("a saturated gyro's flat tops are left out, not read as an effect", "[diagnose]") {
  auto g = noise_only_flight(14);
  double peak = 0;
  for (const auto& w : g.imu.gyro_rad_s) peak = std::max(peak, w.cwiseAbs().maxCoeff());
  const double limit = 0.85 * peak;  // a gyro whose range the throw exceeds
  for (auto& w : g.imu.gyro_rad_s) w = w.cwiseMax(-limit).cwiseMin(limit);
  Flight flight = flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, "clipped");
  const FlightDiagnosis d = diagnose_flight(flight, NominalInertia::of(g.body.inertia));
  CHECK(d.unusable_samples > 0);
  // Clipping bends the readings like a scale error would; with the flat tops out the
  // remaining samples are the nominal motion plus noise.
  CHECK(d.analysis.verdict.effect == Effect::none);
}

TEST_CASE("fewer than 20 usable samples: no verdict, and it says why", "[diagnose]") {
  auto g = noise_only_flight(15);
  Flight flight = flight_from_imu(g.imu, g.body, 0.0, 0.012, "short");
  const FlightDiagnosis d = diagnose_flight(flight, NominalInertia::of(g.body.inertia));
  CHECK(d.analysis.candidates.empty());
  CHECK_FALSE(d.analysis.verdict.confident);
  REQUIRE_FALSE(d.analysis.verdict.could_not_judge.empty());
  CHECK(d.analysis.verdict.could_not_judge.front().find("samples") != std::string::npos);
}
