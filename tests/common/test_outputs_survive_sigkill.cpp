// Outputs stay whole (issue 12, item 8): `aloft diagnose --json --plot` is killed with
// SIGKILL at random moments; whatever output it left under its final name must be
// complete — JSON that parses, CSV whose every row has the header's cells, SVG that
// closes, PNG that ends with its IEND chunk. Temporary files (named NAME.tmp.PID, never
// mistaken for a result) may be left behind.
// `aloft study`'s folder is all old or all new (issue 26): killed 50 times, alternating
// seeds, its folder always equals one whole run's output, and nothing stray is left
// beside or inside it by any run but the one just killed.
#include <signal.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

namespace fs = std::filesystem;

namespace {

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Checks one output file by its type; returns "" when whole, else what is wrong.
std::string whole_or_why(const fs::path& path) {
  const std::string text = contents(path);
  const std::string ext = path.extension().string();
  if (ext == ".json") {
    return nlohmann::json::accept(text) ? "" : "JSON does not parse";
  }
  if (ext == ".svg") {
    return text.find("</svg>") != std::string::npos ? "" : "SVG does not close";
  }
  if (ext == ".png") {
    const bool signature = text.rfind("\x89PNG\r\n\x1a\n", 0) == 0;
    const bool iend = text.size() >= 12 && text.compare(text.size() - 8, 4, "IEND") == 0;
    return signature && iend ? "" : "PNG without its IEND chunk";
  }
  if (ext == ".csv") {
    if (text.empty() || text.back() != '\n') return "CSV does not end with a whole row";
    std::istringstream lines(text);
    std::string line;
    std::getline(lines, line);
    const auto cells = std::count(line.begin(), line.end(), ',');
    while (std::getline(lines, line)) {
      if (std::count(line.begin(), line.end(), ',') != cells) return "CSV row with the wrong cell count";
    }
    return "";
  }
  return "";
}

bool is_temporary(const fs::path& path) {
  return path.filename().string().find(".tmp.") != std::string::npos;
}

pid_t spawn(const std::vector<std::string>& args) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

double run_to_end_seconds(const std::vector<std::string>& args) {
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  ::waitpid(spawn(args), &status, 0);
  REQUIRE(WIFEXITED(status));
  REQUIRE(WEXITSTATUS(status) == 0);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Kills a run of `args` after `seconds` (if still running) and checks `out`; returns how
// many output files it found there to check.
int kill_and_check(const std::vector<std::string>& args, double seconds, const fs::path& out) {
  const pid_t pid = spawn(args);
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (!fs::exists(out)) return 0;
  int checked = 0;
  for (const auto& entry : fs::recursive_directory_iterator(out)) {
    if (!entry.is_regular_file() || is_temporary(entry.path())) continue;
    INFO(entry.path().string() << " after a kill at " << seconds << " s");
    CHECK(whole_or_why(entry.path()) == "");
    ++checked;
  }
  return checked;
}

// A torque-free axisymmetric body's gyro log: ω precesses about the symmetry axis, read
// with 0.02 rad/s of white noise. Without the noise ω_z is the same on every sample, which
// the diagnosis takes for a clipped gyro: it left every sample out and stopped at once,
// writing no plot, and the kills had nothing to cut.
std::string symmetric_top_log() {
  std::ostringstream log;
  log << "t,gx,gy,gz\n";
  const double i1 = 1.0, i3 = 1.6, w3 = 8.0, a = 3.0, rate = (i3 - i1) / i1 * w3;
  std::mt19937 random(3);
  std::normal_distribution<double> noise(0.0, 0.02);
  for (int k = 0; k <= 1000; ++k) {
    const double t = k * 1e-3;
    log << t << ',' << a * std::cos(rate * t) + noise(random) << ',' << a * std::sin(rate * t) + noise(random)
        << ',' << w3 + noise(random) << '\n';
  }
  return log.str();
}

// What `aloft diagnose --json --plot` writes for one flight; the run to the end must leave
// each of them whole, or the kills below would check nothing.
const std::vector<std::string> kDiagnoseOutputs = {"report.json", "plots/gap.png", "plots/gap.svg"};

}  // namespace

TEST_CASE("diagnose outputs are never left truncated by SIGKILL", "[common][outputs][slow]") {
  const fs::path dir = fs::temp_directory_path() / ("aloft-sigkill-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "body.json") << R"({"mass": 1, "inertia": {"principal": [1, 1, 1.6]}})";
  std::ofstream(dir / "imu.csv") << symmetric_top_log();
  const std::string aloft = ALOFT_BINARY;
  std::mt19937 random(12);
  std::uniform_real_distribution<double> share(0.2, 1.05);
  SECTION("aloft diagnose --json --plot") {
    const fs::path out = dir / "diagnose";
    const std::vector<std::string> args = {aloft,    "diagnose",
                                           "--body", (dir / "body.json").string(),
                                           "--imu",  (dir / "imu.csv").string(),
                                           "--json", (out / "report.json").string(),
                                           "--plot", (out / "plots").string()};
    fs::create_directories(out);
    const double full = run_to_end_seconds(args);
    for (const std::string& name : kDiagnoseOutputs) {
      INFO(name << " after a whole run");
      REQUIRE(fs::exists(out / name));
      CHECK(whole_or_why(out / name) == "");
    }
    int checked = 0;
    for (int k = 0; k < 10; ++k) {
      fs::remove_all(out);
      fs::create_directories(out);
      checked += kill_and_check(args, share(random) * full, out);
    }
    WARN("10 kills over a whole run of " << full << " s: " << checked << " output files found whole");
  }
  fs::remove_all(dir);
}

namespace {

// The files of one study output that do not depend on the clock (results.json holds the
// wall time; its seed is checked instead).
const std::vector<std::string> kStudyFiles = {"experiment.csv", "rms_da.csv", "figure.svg", "figure.png",
                                              "results.json"};

using FolderContents = std::map<std::string, std::string>;

FolderContents read_folder(const fs::path& dir) {
  FolderContents out;
  for (const auto& entry : fs::directory_iterator(dir))
    out[entry.path().filename().string()] = contents(entry.path());
  return out;
}

std::vector<std::string> study_args(const fs::path& out, int seed) {
  return {ALOFT_BINARY, "study",     "--out", out.string(), "--mc-samples",
          "40",         "--threads", "2",     "--seed",     std::to_string(seed)};
}

// "" when `dir` is exactly the whole output of the seed-1 or the seed-2 run, else why not.
std::string whole_run_or_why(const fs::path& dir, const FolderContents (&reference)[2]) {
  const FolderContents now = read_folder(dir);
  if (now.size() != kStudyFiles.size())
    return "the folder holds " + std::to_string(now.size()) + " files, not 5";
  const auto results =
      nlohmann::json::parse(now.count("results.json") ? now.at("results.json") : "null", nullptr, false);
  if (!results.is_object() || !results.contains("seed")) return "results.json missing or not whole";
  const int seed = results["seed"].get<int>();
  if (seed != 1 && seed != 2) return "results.json of an unknown run";
  for (const std::string& name : kStudyFiles) {
    if (name == "results.json") continue;
    if (!now.count(name) || now.at(name) != reference[seed - 1].at(name)) {
      return name + " is not the seed-" + std::to_string(seed) + " run's (a mixed folder)";
    }
  }
  return "";
}

// Siblings of `dir` and files inside it that no finished run should leave, except those
// of the processes `allowed` (runs killed so far: a run killed before it cleans up, in its
// first few milliseconds, leaves the earlier killed runs' files for the next run to clean;
// one killed 20 ms in did so under load).
std::vector<std::string> stray_files(const fs::path& dir, const std::vector<pid_t>& allowed) {
  std::vector<std::string> out;
  auto foreign = [&](const std::string& name) {
    for (pid_t pid : allowed) {
      const std::string mine = std::to_string(pid);  // the whole last number: 23 is not 123's
      const std::size_t at = name.size() - std::min(name.size(), mine.size());
      if (at > 0 && name.compare(at, mine.size(), mine) == 0 &&
          !std::isdigit(static_cast<unsigned char>(name[at - 1])))
        return false;
    }
    return true;
  };
  for (const auto& entry : fs::directory_iterator(dir.parent_path())) {
    const std::string name = entry.path().filename().string();
    if (entry.path() != dir && name.find(".aloft-") != std::string::npos && foreign(name))
      out.push_back(name);
  }
  if (fs::exists(dir)) {
    for (const auto& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      if (is_temporary(entry.path()) && foreign(name)) out.push_back(name);
    }
  }
  return out;
}

}  // namespace

TEST_CASE("aloft study's folder is all old or all new after SIGKILL", "[common][outputs][slow]") {
  const fs::path dir = fs::temp_directory_path() / ("aloft-study-swap-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  FolderContents reference[2];
  double full = 0.0;
  for (int seed : {1, 2}) {
    const fs::path ref = dir / ("reference" + std::to_string(seed));
    full = std::max(full, run_to_end_seconds(study_args(ref, seed)));
    reference[seed - 1] = read_folder(ref);
    REQUIRE(reference[seed - 1].size() == kStudyFiles.size());
  }
  REQUIRE(reference[0].at("rms_da.csv") != reference[1].at("rms_da.csv"));

  const fs::path out = dir / "study";
  run_to_end_seconds(study_args(out, 1));
  std::mt19937 random(26);
  std::uniform_real_distribution<double> share(0.0, 1.1);
  int mixed = 0, stray = 0;
  std::vector<pid_t> killed;
  for (int k = 0; k < 50; ++k) {
    const double at = share(random) * full;
    const pid_t pid = spawn(study_args(out, 2 - k % 2));
    std::this_thread::sleep_for(std::chrono::duration<double>(at));
    ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    INFO("kill " << k << " at " << at << " s of " << full << " s");
    const std::string why = fs::exists(out) ? whole_run_or_why(out, reference) : "the folder is gone";
    CHECK(why == "");
    mixed += why != "";
    killed.push_back(pid);
    const std::vector<std::string> left = stray_files(out, killed);
    CHECK(left.empty());
    stray += static_cast<int>(left.size());
  }
  run_to_end_seconds(study_args(out, 1));
  CHECK(stray_files(out, {}).empty());  // the whole run cleaned every killed run's files
  CHECK(whole_run_or_why(out, reference) == "");
  WARN("50 kills: " << mixed << " mixed folders, " << stray << " stray files; a whole run " << full << " s");
  fs::remove_all(dir);
}
