// Issue 8: a marker set that does not fit the body is refused, never diagnosed as `none`.
#include <catch2/catch.hpp>

#include <iterator>

#include "diagnose/1_input/marker_fit_check.hpp"
#include "generator/flight_generator.hpp"

using namespace aloft::host;
using namespace aloft::host::diagnose;

TEST_CASE("markers that do not fit the body are refused; markers that do pass", "[markers]") {
  aloft::generator::FlightSpec spec;
  spec.data = aloft::generator::DataKind::markers;
  const aloft::generator::GeneratedFlight g = aloft::generator::generate_flight(spec, 11);
  PoseFitReport good;
  fit_poses(g.markers, g.body, &good);
  CHECK_FALSE(marker_misfit(g.markers, g.body, good).has_value());
  // The same trial against a body whose marker positions are 30 % off.
  Body wrong = g.body;
  for (auto& m : wrong.markers_m) m.second *= 1.3;
  PoseFitReport bad;
  fit_poses(g.markers, wrong, &bad);
  INFO("mean residual " << bad.mean_rms_residual_m * 1000.0 << " mm");
  CHECK(marker_misfit(g.markers, wrong, bad).has_value());
}

TEST_CASE("a misplaced marker is named; a wrongly scaled set names none", "[markers]") {
  aloft::generator::FlightSpec spec;
  spec.data = aloft::generator::DataKind::markers;
  const aloft::generator::GeneratedFlight g = aloft::generator::generate_flight(spec, 12);
  REQUIRE(g.body.markers_m.size() >= 4);
  Body moved = g.body;
  const auto moved_marker = std::next(moved.markers_m.begin(), 2);
  const std::string culprit = moved_marker->first;
  moved_marker->second += Eigen::Vector3d(0.025, -0.015, 0.01);
  PoseFitReport report;
  fit_poses(g.markers, moved, &report);
  const auto reason = marker_misfit(g.markers, moved, report);
  REQUIRE(reason.has_value());
  INFO(*reason);
  CHECK(reason->find("do not fit: " + culprit + " (") != std::string::npos);
  for (const auto& m : g.body.markers_m) {
    if (m.first != culprit) CHECK(reason->find(m.first + " (") == std::string::npos);
  }

  Body scaled = g.body;
  for (auto& m : scaled.markers_m) m.second *= 1.3;
  PoseFitReport scaled_report;
  fit_poses(g.markers, scaled, &scaled_report);
  const auto scaled_reason = marker_misfit(g.markers, scaled, scaled_report);
  REQUIRE(scaled_reason.has_value());
  INFO(*scaled_reason);
  CHECK(scaled_reason->find("no marker stands out") != std::string::npos);
}
