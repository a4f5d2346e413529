// Outputs stay whole (issue 12, item 8): `aloft study` and `aloft diagnose --json --plot`
// are killed with SIGKILL at random moments; whatever output they left under its final
// name must be complete — JSON that parses, CSV whose every row has the header's cells,
// SVG that closes, PNG that ends with its IEND chunk. Temporary files (named
// NAME.tmp.PID, never mistaken for a result) may be left behind.
#include <signal.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
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

// Kills a run of `args` after `seconds` (if still running) and checks `out`.
void kill_and_check(const std::vector<std::string>& args, double seconds, const fs::path& out) {
  const pid_t pid = spawn(args);
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (!fs::exists(out)) return;
  for (const auto& entry : fs::recursive_directory_iterator(out)) {
    if (!entry.is_regular_file() || is_temporary(entry.path())) continue;
    INFO(entry.path().string() << " after a kill at " << seconds << " s");
    CHECK(whole_or_why(entry.path()) == "");
  }
}

// A torque-free axisymmetric body's gyro log: ω precesses about the symmetry axis.
std::string symmetric_top_log() {
  std::ostringstream log;
  log << "t,gx,gy,gz\n";
  const double i1 = 1.0, i3 = 1.6, w3 = 8.0, a = 3.0, rate = (i3 - i1) / i1 * w3;
  for (int k = 0; k <= 1000; ++k) {
    const double t = k * 1e-3;
    log << t << ',' << a * std::cos(rate * t) << ',' << a * std::sin(rate * t) << ',' << w3 << '\n';
  }
  return log.str();
}

}  // namespace

TEST_CASE("study and diagnose outputs are never left truncated by SIGKILL", "[common][outputs][slow]") {
  const fs::path dir = fs::temp_directory_path() / ("aloft-sigkill-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "body.json") << R"({"mass": 1, "inertia": {"principal": [1, 1, 1.6]}})";
  std::ofstream(dir / "imu.csv") << symmetric_top_log();
  const std::string aloft = ALOFT_BINARY;
  std::mt19937 random(12);
  std::uniform_real_distribution<double> share(0.2, 1.05);

  SECTION("aloft study") {
    const fs::path out = dir / "study";
    const std::vector<std::string> args = {aloft,          "study", "--out",     out.string(),
                                           "--mc-samples", "500",   "--threads", "2"};
    const double full = run_to_end_seconds(args);
    for (int k = 0; k < 10; ++k) {
      fs::remove_all(out);
      kill_and_check(args, share(random) * full, out);
    }
  }
  SECTION("aloft diagnose --json --plot") {
    const fs::path out = dir / "diagnose";
    const std::vector<std::string> args = {aloft,    "diagnose",
                                           "--body", (dir / "body.json").string(),
                                           "--imu",  (dir / "imu.csv").string(),
                                           "--json", (out / "report.json").string(),
                                           "--plot", (out / "plots").string()};
    fs::create_directories(out);
    const double full = run_to_end_seconds(args);
    for (int k = 0; k < 10; ++k) {
      fs::remove_all(out);
      fs::create_directories(out);
      kill_and_check(args, share(random) * full, out);
    }
  }
  fs::remove_all(dir);
}
