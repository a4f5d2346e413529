// The firmware images' result lines (port/cortex_m/flight_lines.hpp: "flight N", then one
// "key value" line per figure) read back, and checked against the flights of `aloft replay
// --json` on the same input: times to the microsecond, counts exactly, floats to the bit.
// For the tests that show firmware = aloft replay (tests/replay, tests/replay_fifo).
#pragma once

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace aloft::test {

using FlightLines = std::map<std::string, std::string>;  // key -> value of one flight

// Every flight of the lines' text, in order.
inline std::vector<FlightLines> flight_lines_of(const std::string& text) {
  std::vector<FlightLines> flights;
  std::istringstream lines(text);
  std::string key, value;
  while (lines >> key >> value) {
    if (key == "flight") flights.emplace_back();
    if (!flights.empty()) flights.back()[key] = value;
    std::getline(lines, value);  // the rest of a header line
  }
  return flights;
}

// The lines print a float's bits as a decimal integer.
inline std::string float_bits_text(double value) {
  const float f = static_cast<float>(value);
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof bits);
  return std::to_string(bits);
}

// The lines' flights say what the report's flights say.
inline void check_flight_lines_match_report(const std::vector<FlightLines>& flights,
                                            const nlohmann::json& report) {
  const auto microseconds_of = [](const std::string& text) { return std::llround(std::stod(text) * 1e6); };
  const auto whole_microseconds = [](const nlohmann::json& s) { return std::llround(double(s) * 1e6); };
  REQUIRE(flights.size() == report["flights"].size());
  REQUIRE_FALSE(flights.empty());
  for (std::size_t i = 0; i < flights.size(); ++i) {
    const nlohmann::json& f = report["flights"][i];
    FlightLines l = flights[i];
    INFO("flight " << i);
    CHECK(microseconds_of(l["release_s"]) == whole_microseconds(f["release_s"]));
    CHECK(microseconds_of(l["landing_s"]) == whole_microseconds(f["landing_s"]));
    CHECK(l["samples"] == std::to_string(int(f["samples"])));
    CHECK(l["gaps"] == std::to_string(int(f["gaps"])));
    CHECK(l["comparisons"] == std::to_string(int(f["comparisons"])));
    CHECK(l["imu_position_from"] == f["imu_position_from"]);
    CHECK(l["rms_da_rad_bits"] == float_bits_text(double(f["rms_da_deg"]) / 57.29577951308232));
    CHECK(l["rms_rel_err_bits"] == float_bits_text(f["rms_rel_err"]));
  }
}

}  // namespace aloft::test
