// Outputs that answer the question (issue 26 item 5): on the made-up session, with Iy
// 3 % high in the body file, the summary says so relative to Ix and Iz; a corrected body
// file holds the true ratio; the session figure is written; on a terminal the flights
// done and the time left are shown; the noise floor is said as a ratio with its square.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "made_up_box.hpp"

using namespace aloft::test;

namespace {
bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }
}  // namespace

TEST_CASE("a session's summary, corrected body, figure and progress", "[first_hour][session]") {
  ScratchDir dir;
  const Session session = made_up_session(dir);
  const std::string body = dir.write("box.json", nominal_box_json());
  const std::string log = dir.write("imu.csv", imu_csv(session.samples, Units{}, true));
  const std::string segments = dir.write("segments.csv", segments_csv(session));
  const std::string fixed = dir.path("out/fixed_body.json"), plots = dir.path("plots");
  // `script` gives the program a terminal, as a user at a shell has: the progress line
  // shows there (stdout and stderr both land in the terminal's transcript).
  const std::string command = std::string(ALOFT_PROGRAM) + " diagnose --body " + body + " --imu " + log +
                              " --segments " + segments + " --corrected-body " + fixed + " --plot " + plots;
  const std::string transcript = dir.path("transcript.txt");
  const int status = std::system(("script -qec '" + command + "' /dev/null > " + transcript).c_str());
  const std::string seen = read_file(transcript);
  CAPTURE(seen);
  REQUIRE(status == 0);
  CHECK(has(seen, "/ 3 flights"));
  CHECK(has(seen, "x the noise floor (RMS residual"));
  CHECK(has(seen, "the body file's Iy is"));
  CHECK(has(seen, "relative to Ix and Iz"));
  REQUIRE(std::filesystem::exists(fixed));
  const nlohmann::json corrected = nlohmann::json::parse(read_file(fixed));
  const nlohmann::json& t = corrected["inertia"]["tensor"];
  // The true box: Iy/Ix = 2 (the body file says 2.06).
  CHECK(t[1][1].get<double>() / t[0][0].get<double>() == Approx(2.0).epsilon(0.01));
  CHECK(corrected["mass"] == 1.0);
  for (const char* file : {"session.svg", "session.png", "flight_throw1.svg"}) {
    CAPTURE(file);
    CHECK(std::filesystem::exists(std::filesystem::path(plots) / file));
  }
}
