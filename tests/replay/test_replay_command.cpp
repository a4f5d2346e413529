// `aloft replay` end to end, as a user runs it: a generated throw replayed from CSV gives
// the release and landing the generator put there, the report has SPEC §5's keys, a right
// tensor agrees where a 10 % wrong one does not, and every bad input ends in one line
// naming the file (and row), exit 2, and no report.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <vector>

#include "common/body_file.hpp"
#include "readers/imu_csv_reader.hpp"
#include "replay/imu_csv_recording.hpp"
#include "replay/replay_run.hpp"
#include "run_aloft.hpp"
#include "throw_generator.hpp"

using aloft::test::run_aloft;
using aloft::test::ScratchDir;
using nlohmann::json;

namespace {

struct Replayed {
  aloft::test::RunResult run;
  json report;
};

// `more`: further options, e.g. " --gyro-filter-us 0".
Replayed replay(const ScratchDir& dir, const std::string& body_text, const std::string& csv_text,
                const std::string& more = "") {
  const std::string body = dir.write("body.json", body_text), csv = dir.write("imu.csv", csv_text);
  const std::string report = dir.path("report.json");
  std::filesystem::remove(report);
  Replayed r;
  r.run = run_aloft(dir, "replay --body '" + body + "' --imu '" + csv + "' --json '" + report + "'" + more);
  INFO("stderr: " << r.run.err);
  REQUIRE(r.run.exit_code == 0);
  r.report = json::parse(aloft::test::read_file(report));
  return r;
}

// A refusal as every one is made: exit 2, one line holding each fragment, no report
// (`report` not written), nothing on stdout.
void check_refused(const aloft::test::RunResult& r, const std::string& report,
                   std::initializer_list<std::string> fragments) {
  INFO("stderr: " << r.err);
  CHECK(r.exit_code == 2);
  CHECK(aloft::test::count_lines(r.err) == 1);
  for (const std::string& fragment : fragments) CHECK(r.err.find(fragment) != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(report));
  CHECK(r.out.empty());
}

}  // namespace

TEST_CASE("replay: a generated throw (r = 0) gives the release and landing put there", "[replay]") {
  ScratchDir dir;
  aloft::test::ThrowSpec spec;
  spec.t_start_s = 12.5;  // the report keeps the CSV's own time base
  const aloft::test::GeneratedThrow g = aloft::test::generate_throw(spec);
  const Replayed r = replay(dir, aloft::test::body_json_text(spec.tensor_kg_m2, Eigen::Vector3d::Zero()),
                            aloft::test::imu_csv_text(g));
  const json& stream = r.report.at("stream");
  CHECK(stream.at("samples") == g.t_s.size());
  CHECK(stream.at("invalid_samples") == 0);
  CHECK(stream.at("clipped_samples") == 0);
  CHECK(stream.at("bytes_skipped") == 0);
  CHECK(stream.at("gaps").empty());
  REQUIRE(r.report.at("flights").size() == 1);
  const json& f = r.report["flights"][0];
  const double release_s = f.at("release_s"), landing_s = f.at("landing_s");
  INFO("true release " << g.release_s << " s, found " << release_s << " s; true landing " << g.landing_s
                       << " s, found " << landing_s << " s");
  CHECK(release_s >= g.release_s);  // never before the true release
  CHECK(release_s <= g.release_s + 0.005);
  CHECK(std::abs(landing_s - g.landing_s) <= 0.005);
  CHECK(f.at("samples") > 0);
  CHECK(f.at("samples") <= spec.flight_samples + 1);
  CHECK(f.at("gaps") == 0);
  CHECK(f.at("imu_position_m") == json::array({0.0, 0.0, 0.0}));
  CHECK(f.at("imu_position_from") == "body");
  CHECK(f.at("rms_da_deg").is_number());
  CHECK(f.at("rms_rel_err").is_number());
  CHECK(r.run.out.find("release_s") != std::string::npos);  // the table on stdout
}

TEST_CASE("replay: a right tensor agrees, a 10 % wrong one does not", "[replay]") {
  ScratchDir dir;
  aloft::test::ThrowSpec spec;
  const aloft::test::GeneratedThrow g = aloft::test::generate_throw(spec);
  const std::string csv = aloft::test::imu_csv_text(g);
  const Eigen::Matrix3d wrong = spec.tensor_kg_m2 * Eigen::Vector3d(1.1, 1.0, 0.9).asDiagonal();
  const json right_flight =
      replay(dir, aloft::test::body_json_text(spec.tensor_kg_m2, {}), csv).report["flights"][0];
  const json wrong_flight = replay(dir, aloft::test::body_json_text(wrong, {}), csv).report["flights"][0];
  const double right_da = right_flight.at("rms_da_deg"), wrong_da = wrong_flight.at("rms_da_deg");
  INFO("rms_da_deg: right tensor " << right_da << ", 10 % wrong " << wrong_da);
  CHECK(right_da < 0.01);
  CHECK(wrong_da > 0.5);
  CHECK(wrong_da > 100.0 * right_da);
  CHECK(double(right_flight.at("rms_rel_err")) < 1e-3);
  CHECK(double(wrong_flight.at("rms_rel_err")) > 10.0 * double(right_flight.at("rms_rel_err")));
  CHECK(right_flight.at("imu_position_from") == "estimated");  // no imu.position in the body
}

TEST_CASE("replay: a drop that does not turn has no verdict, with a note", "[replay]") {
  ScratchDir dir;
  aloft::test::ThrowSpec spec;
  spec.omega_release_rad_s = Eigen::Vector3d::Zero();
  const json f = replay(dir, aloft::test::body_json_text(spec.tensor_kg_m2, {}),
                        aloft::test::imu_csv_text(aloft::test::generate_throw(spec)))
                     .report["flights"][0];
  CHECK(f.at("rms_da_deg").is_null());
  CHECK(f.at("rms_rel_err").is_null());
  CHECK(f.at("note").is_string());
}

TEST_CASE("replay: a recording that ends in the air has landing_s null", "[replay]") {
  ScratchDir dir;
  aloft::test::ThrowSpec spec;
  spec.impact_samples = 0;
  spec.rest_samples = 0;
  const json f = replay(dir, aloft::test::body_json_text(spec.tensor_kg_m2, {}),
                        aloft::test::imu_csv_text(aloft::test::generate_throw(spec)))
                     .report["flights"][0];
  CHECK(f.at("landing_s").is_null());
}

TEST_CASE("replay: a hole in the log is a gap in the stream and in the flight", "[replay]") {
  ScratchDir dir;
  aloft::test::ThrowSpec spec;
  aloft::test::GeneratedThrow g = aloft::test::generate_throw(spec);
  const std::size_t hole = 300;  // in flight: samples 300..304 lost
  const double at_s = g.t_s[hole - 1], length_s = g.t_s[hole + 5] - g.t_s[hole - 1];
  for (auto* v : {&g.t_s}) v->erase(v->begin() + hole, v->begin() + hole + 5);
  g.gyro_rad_s.erase(g.gyro_rad_s.begin() + hole, g.gyro_rad_s.begin() + hole + 5);
  g.accel_m_s2.erase(g.accel_m_s2.begin() + hole, g.accel_m_s2.begin() + hole + 5);
  const json report =
      replay(dir, aloft::test::body_json_text(spec.tensor_kg_m2, {}), aloft::test::imu_csv_text(g)).report;
  REQUIRE(report["stream"]["gaps"].size() == 1);
  CHECK(double(report["stream"]["gaps"][0].at("at_s")) == Approx(at_s).margin(1e-9));
  CHECK(double(report["stream"]["gaps"][0].at("length_s")) == Approx(length_s).margin(1e-9));
  REQUIRE(report["flights"].size() == 1);
  CHECK(report["flights"][0].at("gaps") == 1);
}

TEST_CASE("replay: bad input is one line naming the file and row, exit 2, no report", "[replay][bad]") {
  ScratchDir dir;
  aloft::test::ThrowSpec spec;
  const std::string good_body = dir.write("good.json", aloft::test::body_json_text(spec.tensor_kg_m2, {}));
  const std::string good_csv =
      dir.write("good.csv", aloft::test::imu_csv_text(aloft::test::generate_throw(spec)));
  const std::string report = dir.path("report.json");
  const auto expect_refused = [&](const std::string& body, const std::string& csv,
                                  std::initializer_list<std::string> fragments) {
    check_refused(run_aloft(dir, "replay --body '" + body + "' --imu '" + csv + "' --json '" + report + "'"),
                  report, fragments);
  };
  SECTION("no accelerometer columns") {
    expect_refused(good_body, dir.write("g.csv", "t,gx,gy,gz\n0,0,0,0\n0.001,0,0,0\n"),
                   {"g.csv:1:", "ax,ay,az"});
  }
  SECTION("time going back") {
    expect_refused(
        good_body,
        dir.write("b.csv",
                  "t,gx,gy,gz,ax,ay,az\n0,0,0,0,0,0,9.8\n0.002,0,0,0,0,0,9.8\n0.001,0,0,0,0,0,9.8\n"),
        {"b.csv:4:"});
  }
  SECTION("time standing still") {
    expect_refused(good_body, dir.write("s.csv", "t,gx,gy,gz,ax,ay,az\n0,0,0,0,0,0,9.8\n0,0,0,0,0,0,9.8\n"),
                   {"s.csv:3:"});
  }
  SECTION("closer than a microsecond") {
    expect_refused(good_body,
                   dir.write("u.csv", "t,gx,gy,gz,ax,ay,az\n0,0,0,0,0,0,9.8\n0.0000001,0,0,0,0,0,9.8\n"),
                   {"u.csv:3:", "microsecond"});
  }
  SECTION("a NaN cell") {
    expect_refused(good_body,
                   dir.write("n.csv", "t,gx,gy,gz,ax,ay,az\n0,0,0,0,0,0,9.8\n0.001,0,nan,0,0,0,9.8\n"),
                   {"n.csv:3:", "gy"});
  }
  SECTION("an empty file, and a header without samples") {
    expect_refused(good_body, dir.write("e.csv", ""), {"e.csv"});
    expect_refused(good_body, dir.write("h.csv", "t,gx,gy,gz,ax,ay,az\n"), {"h.csv", "no samples"});
  }
  SECTION("a body file without inertia") {
    expect_refused(dir.write("noi.json", R"({"name": "x", "mass": 1})"), good_csv, {"noi.json", "inertia"});
  }
  SECTION("a body file whose tensor is not one") {
    expect_refused(dir.write("neg.json", R"({"inertia": {"tensor": [[1, 0, 0], [0, 1, 0], [0, 0, 5]]}})"),
                   good_csv, {"neg.json"});
  }
  SECTION("a missing recording") { expect_refused(good_body, dir.path("none.csv"), {"none.csv"}); }
}

TEST_CASE("replay: the command line takes exactly one recording", "[replay][bad]") {
  ScratchDir dir;
  const std::string body = dir.write("b.json", aloft::test::body_json_text(Eigen::Matrix3d::Identity(), {}));
  const std::string fifo = dir.write("f.bin", "");
  const auto neither = run_aloft(dir, "replay --body '" + body + "'");
  CHECK(neither.exit_code == 2);
  CHECK(aloft::test::count_lines(neither.err) == 1);
  const auto both =
      run_aloft(dir, "replay --body '" + body + "' --imu x.csv --fifo '" + fifo + "' --odr-hz 1000");
  CHECK(both.exit_code == 2);
  CHECK(aloft::test::count_lines(both.err) == 1);
  const auto no_rate = run_aloft(dir, "replay --body '" + body + "' --fifo '" + fifo + "'");
  CHECK(no_rate.exit_code == 2);
  CHECK(no_rate.err.find("--odr-hz") != std::string::npos);
  // An empty FIFO file holds no packet: refused in one line.
  const auto fifo_run = run_aloft(dir, "replay --body '" + body + "' --fifo '" + fifo + "' --odr-hz 1000");
  CHECK(fifo_run.exit_code == 2);
  CHECK(aloft::test::count_lines(fifo_run.err) == 1);
}

// The spin-aware release detector (issue 21 item 2, the `release` helper's work) must pass
// this; the plain free-fall detector cannot (|a| = 5 m/s² in flight here), hence
//  until it is merged: then drop the tag.
TEST_CASE("replay: an off-centre accelerometer (imu.position given) still finds the flight", "[replay]") {
  ScratchDir dir;
  aloft::test::ThrowSpec spec;
  spec.imu_position_m = Eigen::Vector3d(0.035, 0.0, 0.01);
  const aloft::test::GeneratedThrow g = aloft::test::generate_throw(spec);
  const json report = replay(dir, aloft::test::body_json_text(spec.tensor_kg_m2, spec.imu_position_m),
                             aloft::test::imu_csv_text(g))
                          .report;
  REQUIRE(report["flights"].size() == 1);
  const json& f = report["flights"][0];
  CHECK(double(f.at("release_s")) >= g.release_s);
  CHECK(double(f.at("release_s")) <= g.release_s + 0.005);
  CHECK(std::abs(double(f.at("landing_s")) - g.landing_s) <= 0.005);
  CHECK(f.at("imu_position_from") == "body");
}

// A body's rotor and a log's rotor_rad_s go together (replay/rotor_match.hpp): either
// without the other is refused with one line naming both files, exit 2, no report; a
// column whose speed is 0 throughout is ignored with a warning.
TEST_CASE("replay: a rotor without its speed, or a speed without a rotor, is refused",
          "[replay][bad][rotor]") {
  ScratchDir dir;
  const aloft::test::ThrowSpec spec = aloft::test::rotor_throw_spec();
  const aloft::test::GeneratedThrow with_rotor = aloft::test::generate_throw(spec);
  aloft::test::ThrowSpec plain_spec = spec;
  plain_spec.rotor.reset();
  const aloft::test::GeneratedThrow plain = aloft::test::generate_throw(plain_spec);
  const std::string rotor_body =
      dir.write("wheel.json", aloft::test::body_json_text(spec.tensor_kg_m2, {}, spec.rotor));
  const std::string plain_body = dir.write("plain.json", aloft::test::body_json_text(spec.tensor_kg_m2, {}));
  const std::string rotor_csv = dir.write("wheel_log.csv", aloft::test::imu_csv_text(with_rotor));
  const std::string plain_csv = dir.write("plain_log.csv", aloft::test::imu_csv_text(plain));
  const std::string report = dir.path("report.json");
  const auto run = [&](const std::string& body, const std::string& input) {
    std::filesystem::remove(report);
    return run_aloft(dir, "replay --body '" + body + "' " + input + " --json '" + report + "'");
  };
  const auto expect_refused = [&](const aloft::test::RunResult& r,
                                  std::initializer_list<std::string> fragments) {
    check_refused(r, report, fragments);
  };
  SECTION("a body with a rotor, a log without its speed") {
    expect_refused(run(rotor_body, "--imu '" + plain_csv + "'"),
                   {"wheel.json", "plain_log.csv", "rotor_rad_s", "torque"});
  }
  SECTION("a log with the speed, a body without a rotor") {
    expect_refused(run(plain_body, "--imu '" + rotor_csv + "'"),
                   {"plain.json", "wheel_log.csv", "rotor_rad_s", "\"rotor\""});
  }
  SECTION("a body with a rotor and a FIFO recording, which holds no rotor speed") {
    // Two packets 3 of an ICM-42688-P at rest (SPEC §5), 1 ms apart: they decode.
    std::string bytes;
    for (const unsigned stamp : {1000u, 2000u}) {
      const unsigned char packet[16] = {0x68,
                                        0,
                                        0,
                                        0,
                                        0,
                                        0x08,
                                        0,
                                        0,
                                        0,
                                        0,
                                        0,
                                        0,
                                        0,
                                        0,
                                        static_cast<unsigned char>(stamp >> 8u),
                                        static_cast<unsigned char>(stamp)};
      bytes.append(reinterpret_cast<const char*>(packet), sizeof packet);
    }
    const std::string fifo = dir.write("rest.bin", bytes);
    expect_refused(run(rotor_body, "--fifo '" + fifo + "' --odr-hz 1000"),
                   {"wheel.json", "rest.bin", "rotor"});
    // The same bytes with the plain body decode and replay: the refusal is the rotor's.
    CHECK(run(plain_body, "--fifo '" + fifo + "' --odr-hz 1000").exit_code == 0);
  }
  SECTION("a speed of 0 throughout and no rotor: the column is ignored, with a warning") {
    aloft::test::GeneratedThrow stopped = plain;
    stopped.rotor_rad_s.assign(plain.t_s.size(), 0.0);
    const std::string csv = dir.write("stopped.csv", aloft::test::imu_csv_text(stopped));
    const auto r = run(plain_body, "--imu '" + csv + "'");
    INFO("stderr: " << r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.err.find("warning") != std::string::npos);
    CHECK(r.err.find("stopped.csv") != std::string::npos);
    CHECK(r.err.find("ignored") != std::string::npos);
    // It replays as the log without the column does.
    const json ignored = json::parse(aloft::test::read_file(report));
    REQUIRE(run(plain_body, "--imu '" + plain_csv + "'").exit_code == 0);
    CHECK(json::parse(aloft::test::read_file(report)).at("flights") == ignored.at("flights"));
  }
}

// What `aloft replay` hands the pipeline of a body with a rotor and a log with its speed:
// the rotor in the settings (float, unit axis) and each sample's speed, flagged.
TEST_CASE("replay: the rotor and its speed reach the pipeline", "[replay][rotor]") {
  ScratchDir dir;
  aloft::test::ThrowSpec spec = aloft::test::rotor_throw_spec();
  spec.rotor->axis = Eigen::Vector3d(0.0, 3.0, 4.0);  // normalised on reading
  const aloft::test::GeneratedThrow g = aloft::test::generate_throw(spec);
  const aloft::host::Body body = aloft::host::read_body_file(
      dir.write("b.json", aloft::test::body_json_text(spec.tensor_kg_m2, {}, spec.rotor)));
  const aloft::OnboardPipelineSettings<float> settings =
      aloft::host::pipeline_settings(aloft::host::replay_settings_from_body(body));
  CHECK(settings.rotor.present());
  CHECK(settings.rotor.inertia_kg_m2 == 2e-5f);
  CHECK(settings.rotor.axis.x() == 0.0f);
  CHECK(settings.rotor.axis.y() == Approx(0.6f));
  CHECK(settings.rotor.axis.z() == Approx(0.8f));
  CHECK(std::abs(settings.rotor.axis.norm() - 1.0f) < 1e-7f);
  const aloft::host::Recording recording = aloft::host::imu_csv_recording(
      aloft::host::read_imu_csv(dir.write("r.csv", aloft::test::imu_csv_text(g))));
  REQUIRE(recording.samples.size() == g.t_s.size());
  CHECK(recording.has_rotor_speed);
  CHECK(recording.max_abs_rotor_rad_s == Approx(800.0).epsilon(1.0 / 256.0));
  for (std::size_t i = 0; i < g.t_s.size(); ++i) {
    INFO("sample " << i);
    CHECK(recording.samples[i].has_rotor_speed());
    CHECK(recording.samples[i].rotor_rad_s == static_cast<float>(g.rotor_rad_s[i]));
  }
  // Without a rotor the settings have none, and a log without the column no speeds.
  aloft::test::ThrowSpec plain = spec;
  plain.rotor.reset();
  CHECK_FALSE(aloft::host::pipeline_settings(
                  aloft::host::replay_settings_from_body(aloft::host::read_body_file(
                      dir.write("p.json", aloft::test::body_json_text(plain.tensor_kg_m2, {})))))
                  .rotor.present());
  const aloft::host::Recording without = aloft::host::imu_csv_recording(aloft::host::read_imu_csv(
      dir.write("p.csv", aloft::test::imu_csv_text(aloft::test::generate_throw(plain)))));
  CHECK_FALSE(without.has_rotor_speed);
  for (const auto& sample : without.samples) CHECK_FALSE(sample.has_rotor_speed());
}

// A replayed flight's principal moments over the body file's, less 1; each inside its
// interval.
namespace {
std::vector<double> replayed_moment_errors(const Replayed& r, const aloft::test::ThrowSpec& spec) {
  REQUIRE(r.report.at("flights").size() == 1);
  const json& t = r.report["flights"][0].at("tensor_estimate");
  INFO(t.dump());
  REQUIRE(t.at("determined") == true);
  REQUIRE(t.at("principal_kg_m2").is_array());
  aloft::InertiaTensor<double> body;
  REQUIRE(aloft::InertiaTensor<double>::make_from_tensor(spec.tensor_kg_m2, body) == aloft::Status::ok);
  std::vector<double> errors;
  for (int i = 0; i < 3; ++i) {
    const double moment = t["principal_kg_m2"][i].get<double>(), truth = body.principal_moments()(i);
    errors.push_back(moment / truth - 1.0);
    CHECK(t["principal_kg_m2_95"][i][0].get<double>() < moment);
    CHECK(t["principal_kg_m2_95"][i][1].get<double>() > moment);
  }
  return errors;
}
}  // namespace

// The user's path to absolute moments: a body file with its rotor, a log with the speed as
// an ESC's telemetry gives it (2 ms late, held 0.5 ms), through `aloft replay --json`, with
// replay's default settings (the gyro's filter taken as aloft's firmware's, the ICM-42688-P's
// UI filter at a quarter of 1 kHz, 640 µs, where this generator's gyro has none). Measured: the
// moments 0.99, 0.92 and 0.81 % high, the smallest just outside its interval (0.8 %) on
// this one flight; the bar held back, 3 %. Nearly all of it is that filter: told there is
// none (--gyro-filter-us 0), 0.22, 0.30 and 0.16 %.
TEST_CASE(
    "replay: a rotor's logged speed gives the flight's absolute moments, within 2 % (0.5 % told the filter)",
    "[replay][rotor][tensor]") {
  ScratchDir dir;
  const aloft::test::ThrowSpec spec = aloft::test::rotor_throw_spec();
  const aloft::test::GeneratedThrow g = aloft::test::generate_throw(spec);
  const std::string body = aloft::test::body_json_text(spec.tensor_kg_m2, {}, spec.rotor);
  const Replayed r = replay(dir, body, aloft::test::imu_csv_text(g));
  CHECK(r.report.at("gyro_filter") == json({{"time_constant_us", 640}, {"from", "firmware"}}));
  for (const double e : replayed_moment_errors(r, spec)) CHECK(std::abs(e) < 0.02);
  // Told the log's filter (none), each moment comes within 0.5 %.
  const Replayed told = replay(dir, body, aloft::test::imu_csv_text(g), " --gyro-filter-us 0");
  CHECK(told.report.at("gyro_filter") == json({{"time_constant_us", 0}, {"from", "option"}}));
  CHECK(told.run.out.find("gyro filter: first-order, 0 µs (--gyro-filter-us)") != std::string::npos);
  for (const double e : replayed_moment_errors(told, spec)) CHECK(std::abs(e) < 0.005);
  // A time constant that is no uint16 of µs is refused, nothing written.
  const std::string report = dir.path("refused.json");
  check_refused(run_aloft(dir, "replay --body '" + dir.path("body.json") + "' --imu '" + dir.path("imu.csv") +
                                   "' --json '" + report + "' --gyro-filter-us 70000"),
                report, {"--gyro-filter-us"});
}
