// Issue 8: a marker set that does not fit the body is refused, never diagnosed as `none`.
#include <catch2/catch.hpp>

#include "diagnose/marker_fit_check.hpp"
#include "generator/flight_generator.hpp"

using namespace aloft::host;
using namespace aloft::host::diagnose;

TEST_CASE("markers that do not fit the body are refused; markers that do pass", "[markers]") {
  aloft::generator::FlightSpec spec;
  spec.data = aloft::generator::DataKind::markers;
  const aloft::generator::GeneratedFlight g = aloft::generator::generate_flight(spec, 11);
  PoseFitReport good;
  fit_poses(g.markers, g.body, &good);
  CHECK_FALSE(marker_misfit(good).has_value());
  // The same trial against a body whose marker positions are 30 % off.
  Body wrong = g.body;
  for (auto& m : wrong.markers_m) m.second *= 1.3;
  PoseFitReport bad;
  fit_poses(g.markers, wrong, &bad);
  INFO("mean residual " << bad.mean_rms_residual_m * 1000.0 << " mm");
  CHECK(marker_misfit(bad).has_value());
}
