// `aloft simulate` end to end: the CSV contract of SPEC §5, the three inertia forms of
// SPEC §2, and bad input: exit non-zero, one line on stderr, no output file.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>

#include <unistd.h>
#include <sys/wait.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_aloft.hpp"

namespace fs = std::filesystem;

namespace {

using aloft::test::run_aloft;
using Run = aloft::test::RunResult;

fs::path scratch_dir() { return aloft::test::program_scratch().dir(); }

void write_text(const fs::path& p, const std::string& text) { aloft::test::write_file(p, text); }

std::vector<std::vector<double>> read_csv_rows(const fs::path& p, std::string* header) {
  std::ifstream in(p);
  std::getline(in, *header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

TEST_CASE("simulate writes t,qw,qx,qy,qz,wx,wy,wz from 0 to the duration inclusive", "[simulate]") {
  const fs::path dir = scratch_dir();
  const std::string bodies[] = {
      R"({"name":"b","mass":12,"inertia":{"shape":{"box":{"x":1,"y":2,"z":3}}}})",
      R"({"name":"p","inertia":{"principal":[13,10,5],"axes":[1,0,0,0]}})",
      R"({"name":"t","inertia":{"tensor":[[13,0,0],[0,10,0],[0,0,5]]}})",
      // The same body with its principal frame turned by 90 degrees about z.
      R"({"name":"r","inertia":{"principal":[10,13,5],"axes":[0.7071067811865476,0,0,0.7071067811865476]}})"};
  std::vector<std::vector<double>> first;
  for (const std::string& body : bodies) {
    write_text(dir / "body.json", body);
    fs::remove(dir / "out.csv");
    const Run run =
        run_aloft("simulate --body " + (dir / "body.json").string() +
                  " --w0 3,-4,12 --q0 1,0,0,0 --duration 0.5 --rate 200 --out " + (dir / "out.csv").string());
    REQUIRE(run.exit_code == 0);
    std::string header;
    const auto rows = read_csv_rows(dir / "out.csv", &header);
    CHECK(header == "t,qw,qx,qy,qz,wx,wy,wz");
    REQUIRE(rows.size() == 101);
    CHECK(rows.front()[0] == 0.0);
    CHECK(std::abs(rows.back()[0] - 0.5) < 1e-12);
    CHECK(rows.front()[5] == 3.0);
    // All forms describe the same box (m = 12 kg, 1 x 2 x 3 m): the same flight.
    if (first.empty()) first = rows;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      for (std::size_t c = 0; c < 8; ++c) CHECK(std::abs(rows[i][c] - first[i][c]) < 1e-9);
    }
  }
}

TEST_CASE("measured moments slightly off the triangle inequality run with a warning", "[simulate]") {
  // The racquet of ../shared/data/real: 0.0207 > 0.01882 + 0.001391 by 1.2 % of the sum.
  const fs::path dir = scratch_dir();
  write_text(dir / "body.json", R"({"inertia":{"principal":[0.01882,0.001391,0.0207]}})");
  fs::remove(dir / "out.csv");
  const Run run = run_aloft("simulate --body " + (dir / "body.json").string() +
                            " --w0 0.1,10,0.1 --duration 0.1 --rate 100 --out " + (dir / "out.csv").string());
  CHECK(run.exit_code == 0);
  CHECK(run.err.find("warning") != std::string::npos);
  CHECK(run.err.find("1.2 %") != std::string::npos);
  CHECK(fs::exists(dir / "out.csv"));
}

TEST_CASE("simulate refuses bad input with one line and writes nothing", "[simulate][bad-input]") {
  const fs::path dir = scratch_dir();
  const std::string good = R"({"inertia":{"principal":[1,2,2.5]}})";
  struct Case {
    std::string body;
    std::string args;
    std::string expected;
  };
  const Case cases[] = {
      {"{not json", "--w0 1,2,3", "not a valid body file: parse error at line 1"},
      {R"({"inertia":{"tensor":[[1,0.5,0],[0,1,0],[0,0,1]]}})", "--w0 1,2,3", "not symmetric"},
      {R"({"inertia":{"principal":[1,1,3]}})", "--w0 1,2,3", "triangle inequality"},
      {R"({"inertia":{"principal":[1,-1,1]}})", "--w0 1,2,3", "positive definite"},
      {R"({"inertia":{"principal":[1,2,2.5],"shape":{"sphere":{"radius":1}}}})", "--w0 1,2,3", "exactly one"},
      {R"({"inertia":{"shape":{"sphere":{"radius":1}}}})", "--w0 1,2,3", "needs \"mass\""},
      {R"({"mass":1,"inertia":{"shape":{"cone":{"radius":1}}}})", "--w0 1,2,3", "unknown shape"},
      {R"({"inertia":{"principal":[1,2,2.5],"axes":[2,0,0,0]}})", "--w0 1,2,3", "unit quaternion"},
      {good, "--w0 1,2", "expected 3"},
      {good, "--w0 1,x,3", "not a number"},
      {good, "--w0 1,2,3 --q0 2,0,0,0", "unit length"},
      {good, "--w0 1,2,nan", "non-finite"},
      {good, "--w0 1,2,3 --integrator euler", "--integrator: euler not in {rk4,splitting}"},
  };
  for (const Case& c : cases) {
    write_text(dir / "body.json", c.body);
    fs::remove(dir / "out.csv");
    std::string args = "simulate --body " + (dir / "body.json").string() + " " + c.args;
    if (c.args.find("--duration") == std::string::npos) args += " --duration 0.1 --rate 100";
    const Run run = run_aloft(args + " --out " + (dir / "out.csv").string());
    INFO(c.body << " " << c.args << " -> " << run.err);
    CHECK(run.exit_code != 0);
    CHECK(run.err.find(c.expected) != std::string::npos);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(dir / "out.csv"));
  }
  const Run missing = run_aloft("simulate --body " + (dir / "nope.json").string() +
                                " --w0 1,2,3 --duration 1 --rate 10 --out " + (dir / "out.csv").string());
  CHECK(missing.exit_code != 0);
  CHECK(missing.err.find("cannot open") != std::string::npos);
  const Run negative = run_aloft("simulate --body " + (dir / "body.json").string() +
                                 " --w0 1,2,3 --duration 1 --rate -10 --out " + (dir / "out.csv").string());
  CHECK(negative.exit_code != 0);
  CHECK_FALSE(fs::exists(dir / "out.csv"));
}
