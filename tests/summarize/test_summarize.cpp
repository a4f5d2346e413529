// `aloft summarize`: the rows of made-up reports whose every value is known, and the
// program end to end (CSV, --json, --flights, bad input).
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "common/commands.hpp"
#include "run_aloft.hpp"
#include "summarize/report_summary.hpp"

using nlohmann::json;

namespace {

json flight_report(const std::string& effect, double before, double after) {
  return {{"verdict",
           {{"effect", effect},
            {"confident", true},
            {"effects", effect == "none" ? json::array()
                                         : json::array({{{"effect", effect}}, {{"effect", "gyro_bias"}}})},
            {"heldout_rms_rel_err_before", before},
            {"heldout_rms_rel_err_after", after}}},
          {"tensor",
           {{"consistent_with_nominal", false},
            {"ratio_best", {1.5, 2.25}},
            {"ratio_95", {{1.4, 1.6}, {2.0, 2.5}}}}}};
}

json session_report() {
  json report = flight_report("inertia_moments", 0.2, 0.05);
  json first = flight_report("none", 0.1, 0.1);
  first["segment"] = "toss 1";
  report["flights"] = json::array({first});
  return report;
}

}  // namespace

TEST_CASE("a flight report is one row with its verdict, shrink and ratio intervals", "[summarize]") {
  const auto rows = aloft::host::report_rows("a.json", flight_report("inertia_moments", 0.2, 0.05), true);
  REQUIRE(rows.size() == 1);
  const json& r = rows[0];
  CHECK(r["scope"] == "flight");
  CHECK(r["verdict"] == "inertia_moments");
  CHECK(r["effects"] == "inertia_moments+gyro_bias");
  CHECK(r["confident"] == true);
  CHECK(r["shrink"].get<double>() == Approx(0.75));  // 1 - 0.05 / 0.2
  CHECK(r["consistent_with_nominal"] == false);
  CHECK(r["ratio_21"] == 1.5);
  CHECK(r["ratio_21_lo"] == 1.4);
  CHECK(r["ratio_21_hi"] == 1.6);
  CHECK(r["ratio_31"] == 2.25);
  CHECK(r["ratio_31_lo"] == 2.0);
  CHECK(r["ratio_31_hi"] == 2.5);
  CHECK(r["segment"].is_null());
}

TEST_CASE("a session report is one row, and one more per flight when asked", "[summarize]") {
  CHECK(aloft::host::report_rows("s.json", session_report(), false).size() == 1);
  const auto rows = aloft::host::report_rows("s.json", session_report(), true);
  REQUIRE(rows.size() == 2);
  CHECK(rows[0]["scope"] == "session");
  CHECK(rows[1]["scope"] == "session_flight");
  CHECK(rows[1]["segment"] == "toss 1");
  CHECK(rows[1]["verdict"] == "none");
  CHECK(rows[1]["effects"] == "");
  CHECK(rows[1]["shrink"].get<double>() == 0.0);
}

TEST_CASE("CSV: a header, one line per row, text with a comma quoted, missing values empty", "[summarize]") {
  json report = flight_report("none", 0.1, 0.1);
  report["verdict"].erase("confident");
  report.erase("tensor");
  const std::string csv = aloft::host::rows_csv(aloft::host::report_rows("x,y.json", report, false));
  CHECK(csv ==
        "report,scope,segment,verdict,effects,confident,shrink,consistent_with_nominal,ratio_21,ratio_21_lo,"
        "ratio_21_hi,ratio_31,ratio_31_lo,ratio_31_hi\n"
        "\"x,y.json\",flight,,none,,,0,,,,,,,\n");
}

TEST_CASE("what is not a report is refused, naming the file", "[summarize]") {
  CHECK_THROWS_AS(aloft::host::report_rows("p.json", json{{"verdict", 3}}, false), aloft::host::Error);
  CHECK_THROWS_WITH(aloft::host::report_rows("p.json", json::array(), false), Catch::Contains("p.json"));
}

TEST_CASE("aloft summarize end to end: CSV, --json, bad input exits 2 with one line", "[summarize][cli]") {
  const auto& scratch = aloft::test::program_scratch();
  const std::string a = scratch.path("a.json"), s = scratch.path("s.json"), bad = scratch.path("bad.json");
  aloft::test::write_file(a, flight_report("gyro_scale", 0.4, 0.1).dump());
  aloft::test::write_file(s, session_report().dump());
  aloft::test::write_file(bad, "{\"verdict\": ");

  const auto csv = aloft::test::run_aloft("summarize '" + a + "' '" + s + "'");
  CHECK(csv.exit_code == 0);
  CHECK(aloft::test::count_lines(csv.out) == 3);
  const auto flights = aloft::test::run_aloft("summarize --flights --json '" + a + "' '" + s + "'");
  CHECK(flights.exit_code == 0);
  const json rows = json::parse(flights.out);
  REQUIRE(rows.size() == 3);
  CHECK(rows[0]["verdict"] == "gyro_scale");
  CHECK(rows[2]["scope"] == "session_flight");

  const auto refused = aloft::test::run_aloft("summarize '" + a + "' '" + bad + "'");
  CHECK(refused.exit_code == 2);
  CHECK(refused.out.empty());
  CHECK(aloft::test::count_lines(refused.err) == 1);
  CHECK(refused.err.find("bad.json") != std::string::npos);
}
