// The generator's flight-controller logs (issue 44): a rotor a motor spins up after release
// against the exact invariant (the body's and the rotor's angular momentum, fixed in
// space), the PT1 low-pass and the 1/16.4 deg/s rounding, and the sessions of
// flight_controller_cases.hpp.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>

#include "first_order_low_pass.hpp"
#include "flight_controller_cases.hpp"
#include "flight_generator.hpp"
#include "perturbed_rigid_body.hpp"

using namespace aloft::generator;

namespace {

// The largest relative change of the angular momentum of body and rotor, in space, over
// 1 s at 1 kHz from a turning start.
double momentum_drift(const PerturbedRigidBody& body, std::vector<FlightState>& states) {
  FlightState start;
  start.omega_body = Eigen::Vector3d(3.0, -7.0, 5.0);
  std::vector<double> times;
  for (int k = 0; k <= 1000; ++k) times.push_back(k * 1e-3);
  states = body.sample(start, times);
  const Eigen::Vector3d l0 = states.front().orientation * body.angular_momentum(states.front(), 0.0);
  double worst = 0.0;
  for (std::size_t k = 0; k < states.size(); ++k) {
    const Eigen::Vector3d l = states[k].orientation * body.angular_momentum(states[k], times[k]);
    worst = std::max(worst, (l - l0).norm() / l0.norm());
  }
  return worst;
}

}  // namespace

TEST_CASE("a rotor spun up after release keeps the angular momentum of body and rotor fixed in space",
          "[generator][spin_up]") {
  FlightPhysics physics;
  physics.inertia_kg_m2 = Eigen::Vector3d(0.004, 0.007, 0.009).asDiagonal();
  physics.spin_up = {Eigen::Vector3d(0.004, -0.002, 0.006), 0.05, 0.06};
  std::vector<FlightState> states;
  CHECK(momentum_drift(PerturbedRigidBody(physics), states) < 1e-9);
  // Before the motor starts nothing turns the rate; after it, the reaction torque does.
  CHECK(physics.spin_up.momentum(0.049).norm() == 0.0);
  CHECK(physics.spin_up.momentum(1.0).isApprox(physics.spin_up.final_momentum_N_m_s *
                                               (1.0 - std::exp(-0.95 / 0.06))));
  CHECK((states[100].omega_body - states[0].omega_body).norm() > 0.1);

  // A ramp (a motor at its current limit): its torque steps at the start and at the ramp's
  // end, 0.05 + 0.1805 s, between samples; L stays fixed through both. A smooth step too.
  physics.spin_up.rise_s = 0.1805;
  for (const SpinUpShape shape : {SpinUpShape::ramp, SpinUpShape::smooth_step}) {
    physics.spin_up.shape = shape;
    CHECK(momentum_drift(PerturbedRigidBody(physics), states) < 1e-9);
    CHECK(physics.spin_up.momentum(0.05 + 0.1805 / 2).isApprox(physics.spin_up.final_momentum_N_m_s / 2));
    CHECK(physics.spin_up.momentum(0.3).isApprox(physics.spin_up.final_momentum_N_m_s));
    CHECK(physics.spin_up.momentum_rate(0.3).norm() == 0.0);
  }
  CHECK(physics.spin_up.momentum_rate(0.05).norm() == 0.0);  // the smooth step's torque starts at zero
}

TEST_CASE("a generated spin-up flight: h at the end, its profile, and L fixed in space",
          "[generator][spin_up]") {
  FlightSpec spec = flight_controller_spec("internal_momentum", "box", 2000.0, 120.0);
  spec.rotor_spin_up = true;
  spec.rotor_fraction_low = 0.2;
  spec.rotor_fraction_high = 0.4;
  const GeneratedFlight g = generate_flight(spec, 17);
  const auto& p = g.truth.params;
  const double start = p.at("start_s").get<double>(), tau = p.at("time_constant_s").get<double>();
  CHECK(start >= 0.02);
  CHECK(start <= 0.08);
  CHECK(tau >= 0.04);
  CHECK(tau <= 0.08);
  const Eigen::Vector3d final_h(p["final_h_N_m_s"][0], p["final_h_N_m_s"][1], p["final_h_N_m_s"][2]);
  const Eigen::Vector3d end_h(p["h_N_m_s"][0], p["h_N_m_s"][1], p["h_N_m_s"][2]);
  CHECK(end_h.isApprox(final_h * (1.0 - std::exp(-(g.truth.duration_s - start) / tau)), 1e-12));
  const Eigen::Vector3d l0 = g.true_samples.front().angular_momentum_world;
  for (const TrueSample& s : g.true_samples) CHECK((s.angular_momentum_world - l0).norm() < 1e-8 * l0.norm());
}

TEST_CASE("a flight controller's log: a PT1's correlation, readings on 1/16.4 deg/s steps",
          "[generator][flight_controller]") {
  const GeneratedFlight g = generate_flight(flight_controller_spec("none", "disc", 4000.0, 50.0), 23);
  for (const Eigen::Vector3d& w : g.imu.gyro_rad_s) {
    for (int a = 0; a < 3; ++a) {
      const double steps = w(a) / kFlightControllerStep;
      CHECK(std::abs(steps - std::round(steps)) < 1e-6);
    }
  }
  // White noise behind y += k (x - y) keeps (2 - k) / k readings per independent sample
  // (fs / (pi fc) for a cutoff well below the rate): 26.5 at 50 Hz and 4 kHz.
  const FirstOrderLowPass filter(50.0, 1.0 / 4000.0);
  CHECK(g.gyro_noise_correlation == Approx((2.0 - filter.gain()) / filter.gain()).epsilon(1e-6));
  CHECK(g.gyro_noise_correlation == Approx(4000.0 / (3.14159265358979323846 * 50.0)).epsilon(0.05));
  // The rounding adds its q / sqrt(12) to the filtered noise's spread.
  const double filtered = 0.02 * std::sqrt(filter.gain() / (2.0 - filter.gain()));
  CHECK(g.gyro_noise_in_readings_rad_s.mean() ==
        Approx(std::hypot(filtered, kFlightControllerStep / std::sqrt(12.0))).epsilon(0.1));
}

TEST_CASE("flight-controller sessions: one sensor a session, each throw its own spin-up",
          "[generator][flight_controller]") {
  const std::vector<SessionCase> cases = flight_controller_session_cases(RotorSeeds::tuning, 4, 3);
  std::set<std::string> kinds;
  std::set<double> rates;
  for (const SessionCase& c : cases) {
    kinds.insert(c.name.substr(0, c.name.rfind('_')));
    const FlightSpec& first = c.flights.front();
    rates.insert(first.imu_rate_hz);
    CHECK(first.gyro_filter_order == 1);
    CHECK(first.gyro_cutoff_hz >= 50.0);
    CHECK(first.gyro_cutoff_hz <= 250.0);
    for (const FlightSpec& f : c.flights) {
      CHECK(f.imu_rate_hz == first.imu_rate_hz);
      CHECK(f.gyro_cutoff_hz == first.gyro_cutoff_hz);
    }
    if (!first.rotor_spin_up) continue;
    const GeneratedFlight a = generate_flight(c.flights[0], c.seed),
                          b = generate_flight(c.flights[1], c.seed);
    const auto axis = [](const GeneratedFlight& g) {
      const auto& h = g.truth.params.at("final_h_N_m_s");
      return Eigen::Vector3d(h[0], h[1], h[2]);
    };
    CHECK(axis(a).normalized().isApprox(axis(b).normalized(), 1e-12));  // one wheel
    CHECK(std::abs(axis(a).norm() / axis(b).norm() - 1.0) > 1e-6);      // its speed each throw's own
    CHECK(a.truth.params.at("start_s").get<double>() != b.truth.params.at("start_s").get<double>());
  }
  CHECK(kinds == std::set<std::string>{"spin_up", "fc_moments", "fc_misaligned", "fc_stopped", "fc_impulse"});
  CHECK(rates.size() >= 3);
}
