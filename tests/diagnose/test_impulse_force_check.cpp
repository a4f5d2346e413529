// An `impulse` verdict checked against the accelerometer (issue 31 item 4): a blow from
// outside shows in the accelerometer as force beyond rotation at the impulse; a step
// that the accelerometer does not see is not a blow, and the verdict says so.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "diagnose/1_input/flight_input.hpp"
#include "diagnose/4_judge/impulse_force_check.hpp"
#include "diagnose/5_flow/diagnosis.hpp"
#include "generator/body_catalogue.hpp"
#include "generator/flight_generator.hpp"

using namespace aloft::host;
using namespace aloft::host::diagnose;

namespace {

aloft::generator::GeneratedFlight impulse_flight(const std::string& body, std::uint64_t seed) {
  aloft::generator::FlightSpec spec;
  spec.body = body;
  spec.effect = "impulse";
  spec.duration_s = 1.2;
  spec.accelerometer = true;
  return aloft::generator::generate_flight(spec, seed);
}

// The same flight's accelerometer as if the step came from inside the body: only the
// rotation's specific force at the sensor (w_dot from the true rates), with the
// generator's accelerometer noise (0.05 m/s² per axis).
Flight without_blow(Flight flight, const aloft::generator::GeneratedFlight& g) {
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 0.05);
  const Eigen::Vector3d r = aloft::generator::body_model(g.truth.body).imu_offset_m;
  const Eigen::Matrix3d to_sensor = g.true_imu_to_body.conjugate().toRotationMatrix();
  for (std::size_t k = 1; k + 1 < g.true_samples.size() && k < flight.size(); ++k) {
    const double dt = g.true_samples[k + 1].t_s - g.true_samples[k - 1].t_s;
    const Eigen::Vector3d w_dot = (g.true_samples[k + 1].omega_body - g.true_samples[k - 1].omega_body) / dt;
    const Eigen::Vector3d& w = g.true_samples[k].omega_body;
    const Eigen::Vector3d n(noise(rng), noise(rng), noise(rng));
    flight.accel_m_s2[k] = to_sensor * (w_dot.cross(r) + w.cross(w.cross(r))) + n;
  }
  return flight;
}

}  // namespace

// Right decisions (blow seen, inner step not) over 4 bodies x the given seeds.
struct Decisions {
  int right = 0, total = 0;
};

Decisions decide(std::uint64_t first_seed, std::uint64_t end_seed) {
  Decisions d;
  for (const char* body : {"box", "tilted_box", "racquet", "cylinder"}) {
    for (std::uint64_t seed = first_seed; seed < end_seed; ++seed) {
      const auto g = impulse_flight(body, seed);
      const double t0 = *g.truth.onset_s;
      Flight flight = flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, body);
      const auto blow = impulse_force(flight, t0);
      const auto inner = impulse_force(without_blow(flight, g), t0);
      REQUIRE(blow);
      REQUIRE(inner);
      d.right += blow->seen + !inner->seen;
      d.total += 2;
    }
  }
  return d;
}

TEST_CASE("impulse force: a blow is seen at the impulse, an inner step is not", "[impulse]") {
  // kSeenOverElsewhere was chosen on seeds 70-72 (every decision right there) and is
  // reported on 170-175, not looked at while choosing: 45 of 48 right (two weak blows at
  // 2.5 and 3.5 x, one inner step on the cylinder at 4.2 x).
  const Decisions tuned = decide(70, 73);
  CHECK(tuned.right == tuned.total);
  const Decisions held_out = decide(170, 176);
  CAPTURE(held_out.right, held_out.total);
  CHECK(held_out.right >= held_out.total * 9 / 10);
}

TEST_CASE("impulse force: a verdict the accelerometer does not back is not confident", "[impulse]") {
  const auto g = impulse_flight("box", 71);
  Flight flight = flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, "box");
  const NominalInertia nominal = NominalInertia::of(g.body.inertia);
  const FlightDiagnosis blow = diagnose_flight(flight, nominal);
  REQUIRE(blow.analysis.verdict.effect == Effect::impulse);
  bool noted = false;
  for (const Note& n : blow.analysis.notes) noted = noted || n.text.find("shows a blow") != std::string::npos;
  CHECK(noted);

  Flight inner_flight = without_blow(flight, g);
  const FlightDiagnosis inner = diagnose_flight(inner_flight, nominal);
  REQUIRE(inner.analysis.verdict.effect == Effect::impulse);
  CHECK_FALSE(inner.analysis.verdict.confident);
  bool said = false;
  for (const std::string& w : inner.analysis.verdict.could_not_judge)
    said = said || w.find("no blow") != std::string::npos;
  CHECK(said);
}
