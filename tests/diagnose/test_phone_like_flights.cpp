// The diagnosis on phone-like flights and multi-flight sessions (issue 8, item 6): the
// generator (generator/phone_like_flights.hpp, an independent code path) logs withheld-
// effect flights the way a phone does (100-500 Hz, jittered stamps, low-pass before the
// noise, 1 mrad/s steps, the phone lying still around each flight) and marks the flights
// in a segments file, which is read here as a user's would be. Scored on the generator's
// side (verdict_score.hpp) from the SPEC §4 report.
#include <catch2/catch.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "diagnose/5_flow/diagnosis.hpp"
#include "diagnose/1_input/flight_input.hpp"
#include "diagnose/6_report/effect_words.hpp"
#include "diagnose/6_report/report_json.hpp"
#include "generator/phone_like_cases.hpp"
#include "generator/phone_like_flights.hpp"
#include "generator/verdict_score.hpp"
#include "readers/segments.hpp"

using namespace aloft::host;
using namespace aloft::host::diagnose;
namespace gen = aloft::generator;
namespace fs = std::filesystem;

namespace {

// The segments file as a user hands it over: written to disk, read by the reader.
std::vector<Segment> read_back(const std::string& csv, const std::string& name) {
  const fs::path path =
      fs::temp_directory_path() / ("aloft_phone_" + std::to_string(::getpid()) + "_" + name + ".csv");
  {
    std::ofstream out(path);
    out << csv;
  }
  std::vector<Segment> segments = read_segments_csv(path.string());
  fs::remove(path);
  return segments;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

TEST_CASE("phone-like flights: right class on >= 90 %, none for noise, confident right >= 95 %",
          "[phone_like]") {
  const auto start = std::chrono::steady_clock::now();
  int right = 0, total = 0, noise_flights = 0, noise_right = 0, confident = 0, confident_right = 0;
  int params_checked = 0, params_right = 0, rest_floors = 0;
  for (const gen::FlightCase& c : gen::phone_like_flight_cases()) {
    const gen::PhoneLikeFlight p = gen::generate_phone_like_flight(c.spec, c.seed);
    const std::vector<Segment> segments = read_back(p.segments_csv, c.name);
    REQUIRE(segments.size() == 1);
    std::vector<Flight> flights = flights_from_segments(p.flight.imu, p.flight.body, segments);
    const FlightDiagnosis d = diagnose_flight(flights.front(), NominalInertia::of(p.flight.body.inertia));
    const nlohmann::json verdict = flight_report(d)["verdict"];
    const gen::VerdictScore score = gen::score_verdict(p.flight.truth, verdict);
    const bool sure = d.analysis.verdict.confident;
    ++total;
    right += score.class_right;
    confident += sure;
    confident_right += sure && score.class_right;
    params_checked += score.params_checked;
    params_right += score.params_checked && score.params_right;
    rest_floors += std::string(d.noise.method) == "rest";
    if (p.flight.truth.effect == "none") {
      ++noise_flights;
      noise_right += score.class_right;
    }
    std::printf("%-30s %-10s %3.0f Hz lp %2.0f Hz noise %.3f floor %.4f (%s) -> %s%s\n", c.name.c_str(),
                c.spec.body.c_str(), p.gyro.rate_hz, p.gyro.cutoff_hz, p.gyro.noise_rad_s,
                d.noise.sigma.mean(), d.noise.method, score.detail.c_str(), sure ? " confident" : "");
    if (!score.class_right)
      std::printf("    window %.3f-%.3f, verdict %s\n", d.start_s, d.end_s, verdict.dump().c_str());
  }
  std::printf(
      "phone-like flights: %d of %d right (%.1f %%); none on %d of %d noise-only; confident %d, right %d; "
      "parameters within the tolerance on %d of %d; floor from rest on %d; %.1f s\n",
      right, total, 100.0 * right / total, noise_right, noise_flights, confident, confident_right,
      params_right, params_checked, rest_floors, seconds_since(start));
  CHECK(total >= 30);
  CHECK(right >= 0.9 * total);
  CHECK(noise_right == noise_flights);
  CHECK(confident_right >= 0.95 * confident);
}

// Issue 8's bar: the right class on every session, the noise-only one included (a 15 Hz
// low-pass on the cylinder's fast precession reads as a 0.2-0.4 % non-uniform gyro scale
// closing 0.5 % of the held-out gap: the practical bar, practical_significance.hpp, calls
// that `none`).
TEST_CASE("phone-like sessions: right class on every one with an effect, a blank keep=false row skipped",
          "[phone_like]") {
  const auto start = std::chrono::steady_clock::now();
  int right = 0, total = 0, confident = 0, confident_right = 0;
  int effect_sessions = 0, effect_right = 0, noise_confident = 0;
  for (const gen::PhoneSessionCase& c : gen::phone_like_session_cases()) {
    const gen::PhoneLikeSession s = gen::generate_phone_like_session(c.flight.spec, c.flights, c.flight.seed);
    const std::vector<Segment> segments = read_back(s.segments_csv, c.flight.name);
    REQUIRE(segments.size() == static_cast<std::size_t>(c.flights));
    std::vector<Flight> flights = flights_from_segments(s.log, s.first.body, segments);
    const SessionDiagnosis d = diagnose_session(flights, NominalInertia::of(s.first.body.inertia), 2);
    const nlohmann::json verdict = session_report(d)["verdict"];
    const gen::VerdictScore score = gen::score_verdict(s.first.truth, verdict);
    const bool sure = d.pooled.verdict.confident;
    ++total;
    right += score.class_right;
    confident += sure;
    confident_right += sure && score.class_right;
    const bool noise_only = s.first.truth.effect == "none";
    effect_sessions += !noise_only;
    effect_right += !noise_only && score.class_right;
    noise_confident += noise_only && sure && d.pooled.verdict.effect != Effect::none;
    std::printf("%-30s %-10s %3.0f Hz lp %2.0f Hz noise %.3f floor %.4f (%s) -> %s%s\n",
                c.flight.name.c_str(), c.flight.spec.body.c_str(), s.gyro.rate_hz, s.gyro.cutoff_hz,
                s.gyro.noise_rad_s, d.flights.front().noise.sigma.mean(), d.flights.front().noise.method,
                score.detail.c_str(), sure ? " confident" : "");
    if (!score.class_right && d.pooled.verdict.chosen >= 0) {
      const Candidate& chosen = d.pooled.candidates[static_cast<std::size_t>(d.pooled.verdict.chosen)];
      std::printf("    %s: params %s, shrink %.3f\n", effect_name(chosen.effect),
                  params_json(chosen.effect, chosen.params).dump().c_str(), chosen.shrink);
    }
  }
  std::printf(
      "phone-like sessions: %d of %d right (%d of %d with an effect); confident %d, right %d; "
      "%.1f s\n",
      right, total, effect_right, effect_sessions, confident, confident_right, seconds_since(start));
  CHECK(total >= 3);
  CHECK(right == total);
  CHECK(effect_right == effect_sessions);
  CHECK(noise_confident == 0);
  CHECK(confident_right >= 0.95 * confident);
}
