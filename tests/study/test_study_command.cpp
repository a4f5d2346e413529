// `aloft study` as a user runs it: the files of SPEC §5, determinism, bad input, and the
// real racquet flights.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

#include "run_aloft.hpp"

using aloft::test::count_lines;
using aloft::test::read_file;
using aloft::test::run_aloft;
using aloft::test::ScratchDir;
using nlohmann::json;

namespace {

void check_summary(const json& s) {
  REQUIRE(s.contains("p10"));
  REQUIRE(s.contains("median"));
  REQUIRE(s.contains("p90"));
  CHECK(s["p10"].get<double>() > 0.0);
  CHECK(s["p10"].get<double>() <= s["median"].get<double>());
  CHECK(s["median"].get<double>() <= s["p90"].get<double>());
}

// The default trial's GF and CP rows (SPEC §5): 873 simulations each, the moments of each
// model as the study computes them.
void check_default_models(const json& models) {
  for (const char* model : {"GF", "CP"}) {
    INFO(model);
    const json& m = models.at(model);
    REQUIRE(m.at("principal_kg_m2").size() == 3);
    CHECK(m.at("simulations").get<int>() == 873);
    check_summary(m.at("rms_da_deg"));
  }
  const json& gf = models["GF"]["principal_kg_m2"];
  CHECK(gf[0].get<double>() == Approx(183.8e-4).margin(0.1e-4));
  CHECK(gf[2].get<double>() == Approx(210.8e-4).margin(0.1e-4));
  const json& cp = models["CP"]["principal_kg_m2"];
  CHECK(cp[0].get<double>() == Approx(203.3e-4));
  CHECK(cp[1].get<double>() == Approx(155.0e-4));
  CHECK(cp[2].get<double>() == Approx(192.5e-4));
}

// Twelve Monte Carlo rows: four bounds of each family (moments in %, axes in degrees, both).
void check_monte_carlo_of_each_family(const json& monte_carlo, int simulations) {
  REQUIRE(monte_carlo.size() == 12);
  int per_family[3] = {0, 0, 0};
  for (const json& mc : monte_carlo) {
    const std::string family = mc.at("family");
    const std::string unit = mc.at("unit");
    CHECK(mc.at("simulations").get<int>() == simulations);
    check_summary(mc.at("rms_da_deg"));
    if (family == "moments") {
      ++per_family[0];
      CHECK(unit == "%");
    } else if (family == "axes") {
      ++per_family[1];
      CHECK(unit == "deg");
    } else {
      CHECK(family == "both");
      ++per_family[2];
    }
    const double bound = mc.at("bound");
    CHECK((bound == 2.5 || bound == 5.0 || bound == 7.5 || bound == 10.0));
  }
  CHECK(per_family[0] == 4);
  CHECK(per_family[1] == 4);
  CHECK(per_family[2] == 4);
}

// experiment.csv holds the default trial's 873 samples; the figure is a PNG and an SVG.
void check_experiment_and_figures(const std::string& out) {
  const std::string experiment = read_file(out + "/experiment.csv");
  CHECK(experiment.rfind("t,qw,qx,qy,qz,wx,wy,wz\n", 0) == 0);
  CHECK(count_lines(experiment) == 1 + 873);
  const std::string png = read_file(out + "/figure.png");
  REQUIRE(png.size() > 8);
  CHECK(png.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  CHECK(read_file(out + "/figure.svg").find("<svg") != std::string::npos);
}

}  // namespace

TEST_CASE("the default study writes the files of SPEC §5, and the same seed gives the same numbers") {
  ScratchDir scratch;
  const auto r =
      run_aloft(scratch, "study --mc-samples 120 --seed 5 --threads 2 --out '" + scratch.path("a") + "'");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("paper") != std::string::npos);  // the side-by-side table
  CHECK(r.out.find("CP") != std::string::npos);

  const json results = json::parse(read_file(scratch.path("a/results.json")));
  check_default_models(results.at("models"));
  check_monte_carlo_of_each_family(results.at("monte_carlo"), 120);
  CHECK(results.at("wall_time_s").get<double>() > 0.0);

  // Both frames by default: SPEC §5's keys in body axes, named by "frame", and every
  // frame under "frames", the world one different.
  CHECK(results.at("frame") == "body");
  CHECK(results.at("frames").at("body").at("models") == results["models"]);
  CHECK(results["frames"]["body"].at("monte_carlo") == results["monte_carlo"]);
  const json& world = results["frames"].at("world");
  check_summary(world.at("models").at("CP").at("rms_da_deg"));
  CHECK(world["models"]["CP"]["rms_da_deg"] != results["models"]["CP"]["rms_da_deg"]);
  REQUIRE(world.at("monte_carlo").size() == 12);
  CHECK(r.out.find("world axes") != std::string::npos);

  const std::string rms = read_file(scratch.path("a/rms_da.csv"));
  CHECK(rms.rfind("analysis,index,rms_da_deg,frame\n", 0) == 0);
  CHECK(count_lines(rms) == 1 + 2 * (2 * 873 + 12 * 120));
  CHECK(rms.find("\nCP,0,") != std::string::npos);
  CHECK(rms.find(",world\n") != std::string::npos);
  check_experiment_and_figures(scratch.path("a"));

  // Same seed, other thread count: the same simulations, to the last digit.
  const auto again =
      run_aloft(scratch, "study --mc-samples 120 --seed 5 --threads 1 --out '" + scratch.path("b") + "'");
  REQUIRE(again.exit_code == 0);
  CHECK(read_file(scratch.path("b/rms_da.csv")) == rms);
  const json other = json::parse(read_file(scratch.path("b/results.json")));
  CHECK(other["models"] == results["models"]);
  CHECK(other["monte_carlo"] == results["monte_carlo"]);

  // Another seed draws other Monte Carlo tensors (the trial and the models stay).
  const auto reseeded =
      run_aloft(scratch, "study --mc-samples 120 --seed 6 --threads 2 --out '" + scratch.path("c") + "'");
  REQUIRE(reseeded.exit_code == 0);
  const json third = json::parse(read_file(scratch.path("c/results.json")));
  CHECK(third["models"] == results["models"]);
  CHECK(third["monte_carlo"] != results["monte_carlo"]);
}

TEST_CASE("--frame world reports the world frame alone, with the same numbers as both") {
  ScratchDir scratch;
  const std::string common = "study --mc-samples 30 --seed 3 --threads 2 --out '";
  const auto both = run_aloft(scratch, common + scratch.path("both") + "'");
  const auto world = run_aloft(scratch, common + scratch.path("world") + "' --frame world");
  INFO(world.err);
  REQUIRE(both.exit_code == 0);
  REQUIRE(world.exit_code == 0);
  const json b = json::parse(read_file(scratch.path("both/results.json")));
  const json w = json::parse(read_file(scratch.path("world/results.json")));
  CHECK(w.at("frame") == "world");
  CHECK(w.at("frames").size() == 1);
  CHECK(w["models"] == b["frames"]["world"]["models"]);
  CHECK(w["monte_carlo"] == b["frames"]["world"]["monte_carlo"]);
  const std::string rms = read_file(scratch.path("world/rms_da.csv"));
  CHECK(count_lines(rms) == 1 + 2 * 873 + 12 * 30);
  CHECK(rms.find(",body\n") == std::string::npos);
}

TEST_CASE("the throw and the axes sampler are options, recorded in results.json") {
  ScratchDir scratch;
  const auto r = run_aloft(scratch,
                           "study --mc-samples 20 --threads 2 --spin-rate 1 --spin-tilt 80 "
                           "--spin-azimuth 10 --duration 0.5 --marker-noise 0.05 "
                           "--marker-layout side --axes-sampler cardan --frame body --out '" +
                               scratch.path("o") + "'");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const json results = json::parse(read_file(scratch.path("o/results.json")));
  const json& trial = results.at("trial");
  CHECK(trial.at("spin_rate_rev_s").get<double>() == 1.0);
  CHECK(trial.at("spin_tilt_deg").get<double>() == 80.0);
  CHECK(trial.at("spin_azimuth_deg").get<double>() == 10.0);
  CHECK(trial.at("flight_time_s").get<double>() == 0.5);
  CHECK(trial.at("marker_noise_m").get<double>() == Approx(0.05e-3));
  CHECK(trial.at("marker_layout") == "side");
  CHECK(trial.at("samples").get<int>() == 501);
  CHECK(results.at("axes_sampler") == "cardan");
  CHECK(results.at("models").at("GF").at("simulations").get<int>() == 501);
  const json& w = trial.at("initial_omega_body_rad_s");
  const double rate =
      std::sqrt(w[0].get<double>() * w[0].get<double>() + w[1].get<double>() * w[1].get<double>() +
                w[2].get<double>() * w[2].get<double>());
  CHECK(rate == Approx(2.0 * M_PI));
  CHECK(w[2].get<double>() == Approx(2.0 * M_PI * std::cos(80.0 * M_PI / 180.0)));
}

TEST_CASE("the paper-body throw gives GF and CP rows near the paper's, as calibrated") {
  ScratchDir scratch;
  const auto r = run_aloft(scratch,
                           "study --throw paper-body --frame body --mc-samples 10 "
                           "--threads 2 --out '" +
                               scratch.path("o") + "'");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const json results = json::parse(read_file(scratch.path("o/results.json")));
  CHECK(results.at("trial").at("preset") == "paper-body");
  for (const char* model : {"GF", "CP"}) {
    const json& m = results.at("models").at(model);
    for (const char* key : {"p10", "median", "p90"}) {
      INFO(model << " " << key);
      // The search left an RMS difference of 0.40 deg over the six numbers.
      CHECK(m.at("rms_da_deg").at(key).get<double>() ==
            Approx(m.at("paper_rms_da_deg").at(key).get<double>()).margin(1.0));
    }
  }
}

namespace {

// An output folder that holds a previous run's results.json, and a valid body file: a
// refused study writes nothing there, replaces nothing and leaves no temporary behind.
struct PreviousRun {
  ScratchDir scratch;
  std::string out = scratch.path("out");
  std::string body;

  PreviousRun() {
    std::filesystem::create_directories(out);
    scratch.write("out/results.json", "previous run\n");
    body = scratch.write("body.json",
                         R"({"name": "box", "mass": 1.0, "inertia": {"principal": [0.01, 0.02, 0.025]}})");
  }
  void check_untouched() const {
    std::size_t files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(out)) {
      (void)entry;
      ++files;
    }
    CHECK(files == 1);
    CHECK(read_file(out + "/results.json") == "previous run\n");
  }
};

}  // namespace

TEST_CASE("bad input files to study: one line naming the file, non-zero exit, nothing written") {
  const PreviousRun previous;
  const ScratchDir& scratch = previous.scratch;
  const std::string& out = previous.out;
  const std::string& body = previous.body;

  SECTION("a NaN gyro sample") {
    const std::string imu = scratch.write("imu.csv", "t,gx,gy,gz\n0,1,2,3\n0.01,1,nan,3\n0.02,1,2,3\n");
    const auto r = run_aloft(scratch, "study --body '" + body + "' --imu '" + imu + "' --out '" + out + "'");
    CHECK(r.exit_code != 0);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.find("imu.csv") != std::string::npos);
  }
  SECTION("a body file that does not exist") {
    const auto r = run_aloft(
        scratch, "study --body '" + scratch.path("none.json") + "' --poses x.csv --out '" + out + "'");
    CHECK(r.exit_code != 0);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.find("none.json") != std::string::npos);
  }
  SECTION("a flight too short to study") {
    const std::string imu =
        scratch.write("imu.csv", "t,gx,gy,gz\n0,1,2,3\n0.01,1,2,3\n0.02,1,2,3\n0.5,1,2,3\n");
    const std::string segments = scratch.write("segments.csv", "segment,start,end\n1,0.1,0.4\n");
    const auto r = run_aloft(scratch, "study --body '" + body + "' --imu '" + imu + "' --segments '" +
                                          segments + "' --out '" + out + "'");
    CHECK(r.exit_code != 0);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.find("segment 1") != std::string::npos);
  }
  SECTION("--markers without --body") {
    const auto r = run_aloft(scratch, "study --markers x.trc --out '" + out + "'");
    CHECK(r.exit_code != 0);
    CHECK(count_lines(r.err) == 1);
  }
  previous.check_untouched();
}

TEST_CASE("bad options to study: one line, exit code 2, nothing written") {
  const PreviousRun previous;
  const ScratchDir& scratch = previous.scratch;
  const std::string& out = previous.out;
  const std::string& body = previous.body;

  SECTION("a throw option out of range") {
    const auto r = run_aloft(scratch, "study --spin-rate -1 --out '" + out + "'");
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.find("--spin-rate") != std::string::npos);
  }
  SECTION("calibration with a searched option") {
    const auto r = run_aloft(scratch, "study --calibrate-to-paper --spin-rate 2 --out '" + out + "'");
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
  }
  SECTION("an unknown throw preset") {
    const auto r = run_aloft(scratch, "study --throw paper --out '" + out + "'");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--throw") != std::string::npos);
  }
  SECTION("an unknown axes sampler") {
    const auto r = run_aloft(scratch, "study --axes-sampler euler --out '" + out + "'");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("--axes-sampler") != std::string::npos);
  }
  SECTION("a throw option with a recording") {
    const std::string imu = scratch.write("imu.csv", "t,gx,gy,gz\n0,1,2,3\n0.01,1,2,3\n0.02,1,2,3\n");
    const auto r = run_aloft(
        scratch, "study --body '" + body + "' --imu '" + imu + "' --spin-rate 2 --out '" + out + "'");
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
  }
  SECTION("an unknown frame") {
    const auto r = run_aloft(scratch, "study --frame lab --out '" + out + "'");
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
    CHECK(r.err.find("--frame") != std::string::npos);
  }
  SECTION("the world frame of an IMU recording, which has no orientation") {
    const std::string imu = scratch.write("imu.csv", "t,gx,gy,gz\n0,1,2,3\n0.01,1,2,3\n0.02,1,2,3\n");
    const auto r = run_aloft(
        scratch, "study --body '" + body + "' --imu '" + imu + "' --frame world --out '" + out + "'");
    CHECK(r.exit_code == 2);
    CHECK(count_lines(r.err) == 1);
  }
  previous.check_untouched();
}

TEST_CASE("the study runs on every racquet flight of both sessions") {
  const std::string data = aloft::test::shared_data_dir();
  if (data.empty()) {
    WARN("skipped: ../shared/data is not in this checkout");
    return;
  }
  const std::string racquet = data + "/real/racquet";
  // body.json's moments break the triangle inequality by 1.2 % of their sum, inside
  // their stated uncertainty: the body reader accepts them with a warning, and the
  // Monte Carlo draws are held to the same slack (host_sim/common/body_file.hpp).
  const std::string body = racquet + "/body.json";
  const struct {
    const char* session;
    std::size_t flights;
  } sessions[] = {{"2025-01-16_17-10-11", 6}, {"2025-01-23_18-29-01", 5}};
  for (const auto& s : sessions) {
    INFO(s.session);
    ScratchDir scratch;
    const std::string dir = racquet + "/" + s.session;
    const auto r =
        run_aloft(scratch, "study --body '" + body + "' --imu '" + dir + "/gyro.csv' --segments '" + dir +
                               "/segments.csv' --mc-samples 100 --out '" + scratch.path("out") + "'");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    const json results = json::parse(read_file(scratch.path("out/results.json")));
    REQUIRE(results.at("flights").size() == s.flights);
    for (const json& f : results["flights"]) {
      check_summary(f.at("models").at("nominal").at("rms_da_deg"));
      CHECK(f.at("monte_carlo").size() == 12);
      CHECK(f.at("samples").get<int>() > 50);  // about 100 Hz over about a second
    }
    check_summary(results.at("models").at("nominal").at("rms_da_deg"));
    CHECK(results.at("frame") == "body");  // gyro only: no world frame
    CHECK(results.at("frames").size() == 1);
  }
}
