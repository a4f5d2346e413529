// The command line's contract, swept over bad command lines: each exits 2 with exactly
// one line on stderr naming the bad word (and the valid choices where there are some),
// before any work is done; --version and --help succeed; simulate writes numbers at the
// precision they carry.
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_aloft.hpp"

namespace fs = std::filesystem;

namespace {

using aloft::test::program_scratch;
using aloft::test::read_file;
using aloft::test::run_aloft;
using Run = aloft::test::RunResult;

fs::path scratch() { return program_scratch().dir(); }

const std::string body = std::string(ALOFT_EXAMPLES) + "/gf_cylinder.json";
const std::string imu_missing = (scratch() / "no_such_log.csv").string();

struct BadLine {
  std::string args;
  std::vector<std::string> must_name;  // words the one line must contain
};

const std::string simulate_base = "simulate --body " + body + " --w0 1,2,3";
const std::string simulate_ok = simulate_base + " --duration 0.1 --rate 100";

}  // namespace

TEST_CASE("every bad command line exits 2 with one line naming the problem", "[cli]") {
  const std::string file_as_folder = body + "/inside";
  const std::vector<BadLine> sweep = {
      {"", {"no command given", "simulate", "study", "inspect", "diagnose"}},
      {"frobnicate", {"unknown command frobnicate", "simulate", "diagnose"}},
      {"studdy", {"unknown command studdy", "did you mean study?"}},
      // CLI11 would answer these with the program's help and exit 0.
      {"frobnicate --help", {"unknown command frobnicate", "summarize"}},
      {"summarise --help", {"unknown command summarise", "did you mean summarize?"}},
      {"--frobnicate", {"unknown option --frobnicate"}},
      {"simulate --bdy " + body, {"unknown option --bdy", "did you mean --body?", "--w0"}},
      {"simulate --w0 1,2,3", {"--body is required"}},
      {simulate_ok + " --out x.csv --integrator euler", {"--integrator", "euler", "rk4", "splitting"}},
      {simulate_ok + " --out x.csv extra", {"unexpected argument extra"}},
      {simulate_ok + " --out " + scratch().string(), {"--out", "is a folder"}},
      {simulate_ok + " --out " + file_as_folder + "/x.csv", {"--out", body, "not a folder"}},
      {simulate_base + " --rate 100 --out x.csv --duration soon", {"--duration", "soon"}},
      {simulate_ok + " --out x.csv --rate 5", {"--rate"}},
      {"study --seed -1", {"--seed", "-1", "whole number"}},
      {"study --seed 1.5", {"--seed", "1.5"}},
      {"study --mc-samples -5", {"--mc-samples", "-5"}},
      {"study --threads two", {"--threads", "two"}},
      {"study --out " + body, {"--out", body, "not a folder"}},
      {"study --out " + file_as_folder, {"--out", "is not a folder"}},
      {"study --seeds 3", {"unknown option --seeds", "did you mean --seed?"}},
      {"inspect", {"file is required"}},
      {"diagnose --body " + body + " --imu " + imu_missing + " --json " + file_as_folder + "/r.json",
       {"--json", "not a folder"}},
      {"diagnose --body " + body + " --imu " + imu_missing + " --plot " + body, {"--plot", "not a folder"}},
      {"diagnose --body " + body + " --imu " + imu_missing + " --threads 0", {"--threads", "0"}},
      {"diagnose --body " + body + " --imus x.csv", {"unknown option --imus", "did you mean --imu?"}},
  };
  for (const BadLine& bad : sweep) {
    CAPTURE(bad.args);
    const Run r = run_aloft(bad.args);
    CAPTURE(r.err);
    CHECK(r.exit_code == 2);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(r.out.empty());
    for (const std::string& word : bad.must_name) CHECK(r.err.find(word) != std::string::npos);
  }
}

TEST_CASE("--version prints the project version and --help succeeds", "[cli]") {
  const Run version = run_aloft("--version");
  CHECK(version.exit_code == 0);
  CHECK(version.out == std::string("aloft ") + ALOFT_VERSION + "\n");
  const Run help = run_aloft("diagnose --help");
  CHECK(help.exit_code == 0);
  CHECK(help.out.find("--threads") != std::string::npos);
}

TEST_CASE("help texts cite no file a user does not have and show no CLI11 notation", "[cli]") {
  for (const char* command :
       {"", "simulate", "study", "inspect", "diagnose", "replay", "records", "summarize"}) {
    CAPTURE(command);
    const Run help = run_aloft(std::string(command) + " --help");
    CHECK(help.exit_code == 0);
    CHECK(help.out.find("SPEC") == std::string::npos);
    CHECK(help.out.find("INT:") == std::string::npos);
    CHECK(help.out.find("in [") == std::string::npos);
  }
  const Run diagnose = run_aloft("diagnose --help");
  CHECK(diagnose.out.find("default: every core") != std::string::npos);  // as study
  CHECK(diagnose.out.find("--gyro-units") != std::string::npos);
  CHECK(run_aloft("study --help").out.find("default: every core") != std::string::npos);
}

TEST_CASE("an output file's missing folders are made, as --plot makes its folder", "[cli]") {
  const fs::path json = scratch() / "new" / "deeper" / "replay.json";
  const Run r = run_aloft("replay --body " + std::string(ALOFT_EXAMPLES) + "/throw_body.json --imu " +
                          std::string(ALOFT_EXAMPLES) + "/throw_imu.csv --json " + json.string());
  CAPTURE(r.err);
  CHECK(r.exit_code == 0);
  CHECK(fs::is_regular_file(json));
  const fs::path csv = scratch() / "made" / "traj.csv";
  CHECK(run_aloft(simulate_ok + " --out " + csv.string()).exit_code == 0);
  CHECK(fs::is_regular_file(csv));
}

TEST_CASE("simulate writes each number at the precision it carries", "[cli]") {
  const fs::path csv = scratch() / "traj.csv";
  const Run r = run_aloft(simulate_base + " --duration 0.1 --rate 200 --out " + csv.string());
  REQUIRE(r.exit_code == 0);
  std::istringstream rows(read_file(csv));
  std::string row;
  std::vector<std::string> times;
  std::getline(rows, row);  // header
  while (std::getline(rows, row)) times.push_back(row.substr(0, row.find(',')));
  REQUIRE(times.size() == 21);
  CHECK(times[1] == "0.005");
  CHECK(times[3] == "0.015");
  CHECK(times[20] == "0.1");
  std::istringstream again(read_file(csv));
  std::getline(again, row);
  std::getline(again, row);
  CHECK(row.rfind("0,1,0,0,0,1,2,3", 0) == 0);  // the initial state as given
}
