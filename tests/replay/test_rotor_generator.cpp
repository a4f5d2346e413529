// The generators' rotor (rotor_flight.hpp, throw_generator.hpp) against exact answers and
// conservation laws: the gyro must read the true solution of I ω̇ + ω × (I ω + h) = −ḣ and
// the accelerometer the specific force, and the logged speed must be what an ESC's
// telemetry gives (quantised, delayed, held).
#include <catch2/catch.hpp>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

#include "rotor_flight.hpp"
#include "throw_generator.hpp"

using aloft::test::GeneratedThrow;
using aloft::test::GyrostatState;
using aloft::test::RotorFlight;
using aloft::test::RotorProfile;
using aloft::test::RotorTelemetry;
using aloft::test::ThrowSpec;

namespace {

ThrowSpec noise_free_rotor_throw() {
  ThrowSpec spec = aloft::test::rotor_throw_spec();
  spec.gyro_noise_rad_s = 0.0;
  spec.accel_noise_m_s2 = 0.0;
  return spec;
}

// The largest drift of the world momentum, relative to its size, over a flight of `seconds`
// sampled every millisecond; and the same of R(q) I ω alone (without the rotor's h).
struct Drift {
  double total = 0.0;
  double without_rotor = 0.0;
};
Drift momentum_drift(const RotorFlight& flight, const Eigen::Matrix3d& inertia, GyrostatState s,
                     double seconds) {
  const Eigen::Vector3d l0 = flight.world_momentum(0.0, s);
  const Eigen::Vector3d body0 = s.q * (inertia * s.w);
  Drift d;
  for (int k = 1; k <= int(seconds * 1000.0); ++k) {
    flight.advance((k - 1) * 1e-3, 1e-3, s);
    const double t = k * 1e-3;
    d.total = std::max(d.total, (flight.world_momentum(t, s) - l0).norm() / l0.norm());
    d.without_rotor = std::max(d.without_rotor, (s.q * (inertia * s.w) - body0).norm() / l0.norm());
  }
  return d;
}

}  // namespace

TEST_CASE("rotor flight: the world angular momentum I ω + h is constant", "[rotor][generator]") {
  const ThrowSpec spec = noise_free_rotor_throw();
  for (const bool first_order : {false, true}) {
    for (const double full : {800.0, -1500.0}) {
      RotorProfile p = spec.rotor->profile;
      p.first_order = first_order;
      p.full_rad_s = full;
      const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
      const RotorFlight flight(spec.tensor_kg_m2, spec.rotor->inertia_kg_m2, axis, p);
      GyrostatState s;
      s.w = spec.omega_release_rad_s;
      const Drift d = momentum_drift(flight, spec.tensor_kg_m2, s, 0.9);
      INFO("first order " << first_order << ", full " << full << " rad/s: drift " << d.total << ", without h "
                          << d.without_rotor);
      CHECK(d.total < 1e-10);
      // The rotor carries a large share of the momentum mid-flight: leaving h out breaks it.
      CHECK(d.without_rotor > 0.1);
    }
  }
}

TEST_CASE("rotor throw: the generator's flight conserves the world momentum", "[rotor][generator]") {
  const GeneratedThrow g = aloft::test::generate_throw(noise_free_rotor_throw());
  const double l = g.momentum_world_release.norm();
  REQUIRE(l > 0.01);
  CHECK((g.momentum_world_landing - g.momentum_world_release).norm() / l < 1e-10);
}

TEST_CASE("rotor throw: a spin about the rotor's principal axis has the exact answer", "[rotor][generator]") {
  // I ω_z' = −ḣ_z, the other axes untouched: ω_z(t) = ω_z(0) − J (s(t) − s(0)) / I_z.
  ThrowSpec spec = noise_free_rotor_throw();
  spec.tensor_kg_m2 = Eigen::Vector3d(0.0021, 0.0032, 0.0045).asDiagonal();
  spec.omega_release_rad_s = Eigen::Vector3d(0.0, 0.0, 9.0);
  spec.imu_position_m = Eigen::Vector3d(0.02, -0.01, 0.005);
  const GeneratedThrow g = aloft::test::generate_throw(spec);
  const double j = spec.rotor->inertia_kg_m2, iz = 0.0045;
  const std::size_t release = std::size_t(spec.still_samples + spec.swing_samples);
  double worst = 0.0, swing = 0.0;
  for (std::size_t k = release; k < release + std::size_t(spec.flight_samples); ++k) {
    const double exact = 9.0 - j * g.rotor_true_rad_s[k] / iz;
    worst = std::max(worst, std::abs(g.gyro_rad_s[k].z() - exact));
    worst = std::max(worst, g.gyro_rad_s[k].head<2>().norm());
    swing = std::max(swing, std::abs(exact - 9.0));
  }
  INFO("worst error " << worst << " rad/s; the rotor takes up to " << swing << " rad/s");
  CHECK(worst < 1e-12);
  CHECK(swing == Approx(j * 800.0 / iz).epsilon(1e-12));  // it reached full speed in flight
}

TEST_CASE("rotor throw: the accelerometer reads the specific force of the gyrostat", "[rotor][generator]") {
  ThrowSpec spec = noise_free_rotor_throw();
  spec.imu_position_m = Eigen::Vector3d(0.03, 0.01, -0.02);
  const GeneratedThrow g = aloft::test::generate_throw(spec);
  const Eigen::Vector3d& r = spec.imu_position_m;
  const std::size_t release = std::size_t(spec.still_samples + spec.swing_samples);
  const double dt = 1.0 / spec.rate_hz;
  const Eigen::Matrix3d& inertia = spec.tensor_kg_m2;
  double worst = 0.0, rotor_share = 0.0;
  // ω̇ from the gyro by central differences (error O(dt²) ω‴, well under 1e-3 m/s² here),
  // away from the profile's corners where ḣ jumps.
  const RotorProfile p = spec.rotor->profile;
  for (std::size_t k = release + 1; k + 1 < release + std::size_t(spec.flight_samples); ++k) {
    const double t_after_release = g.t_s[k] - g.release_s;
    bool near_corner = false;
    for (const double c : p.corners()) near_corner = near_corner || std::abs(t_after_release - c) < 2.5 * dt;
    if (near_corner) continue;
    const Eigen::Vector3d w = g.gyro_rad_s[k];
    const Eigen::Vector3d w_dot = (g.gyro_rad_s[k + 1] - g.gyro_rad_s[k - 1]) / (2.0 * dt);
    const Eigen::Vector3d expected = w_dot.cross(r) + w.cross(w.cross(r));
    worst = std::max(worst, (g.accel_m_s2[k] - expected).norm());
    // What a torque-free body would read there: the rotor's torque is not in it.
    const Eigen::Vector3d torque_free = inertia.inverse() * -w.cross(inertia * w);
    rotor_share =
        std::max(rotor_share, (g.accel_m_s2[k] - torque_free.cross(r) - w.cross(w.cross(r))).norm());
  }
  INFO("worst " << worst << " m/s^2; the rotor's torque adds up to " << rotor_share << " m/s^2");
  CHECK(worst < 2e-3);
  CHECK(rotor_share > 0.2);
}

TEST_CASE("rotor telemetry: DShot's quantised, delayed, held speed", "[rotor][generator]") {
  RotorTelemetry telemetry;
  telemetry.pole_pairs = 7;
  // 9 significant bits of the electrical period: within 1/256 of the speed (and never
  // above it: the period is truncated, so the speed read is at least the true one's).
  for (const double speed : {20.0, 100.0, 333.3, 800.0, 1500.0, -640.0}) {
    const double read = telemetry.quantised(speed);
    INFO(speed << " rad/s reads " << read);
    CHECK(std::abs(read - speed) <= std::abs(speed) / 256.0);
    CHECK(std::abs(read) >= std::abs(speed));
    CHECK(read * speed > 0.0);
  }
  // Below 917 eRPM (a period of 65,408 µs; 13.72 rad/s at 7 pole pairs) the period does
  // not fit: stopped.
  CHECK(telemetry.quantised(13.70) == 0.0);
  CHECK(telemetry.quantised(13.74) >= 13.74);
  CHECK(telemetry.quantised(0.0) == 0.0);
  // Quantised for real: two speeds 0.1 % apart near full speed read the same.
  CHECK(telemetry.quantised(800.0) == telemetry.quantised(800.8));

  // Delay and hold: the value at t is the speed of (the last frame before t) − delay.
  RotorProfile p;
  p.start_s = 0.1;
  p.spin_up_s = 0.2;
  p.full_rad_s = 1000.0;
  telemetry.period_s = 0.001;
  telemetry.delay_s = 0.003;
  telemetry.first_frame_s = 0.0;
  const double t = 0.2004;  // last frame 0.200, reporting the speed at 0.197
  CHECK(telemetry.logged(t, p) == telemetry.quantised(p.speed(0.197)));
  CHECK(telemetry.logged(0.2009, p) == telemetry.logged(t, p));
  CHECK(telemetry.logged(0.2011, p) > telemetry.logged(t, p));
  CHECK(telemetry.logged(0.1029, p) == 0.0);  // the spin-up is not seen for 3 ms and more
}

TEST_CASE("rotor throw: the log carries the telemetry, the profile is as specified", "[rotor][generator]") {
  const ThrowSpec spec = noise_free_rotor_throw();
  const GeneratedThrow g = aloft::test::generate_throw(spec);
  REQUIRE(g.rotor_rad_s.size() == g.t_s.size());
  const RotorProfile& p = spec.rotor->profile;
  double peak = 0.0, worst_lag = 0.0;
  for (std::size_t k = 0; k < g.t_s.size(); ++k) {
    const double after = g.t_s[k] - g.release_s;
    if (after < p.start_s) CHECK(g.rotor_rad_s[k] == 0.0);
    peak = std::max(peak, g.rotor_rad_s[k]);
    worst_lag = std::max(worst_lag, std::abs(g.rotor_rad_s[k] - g.rotor_true_rad_s[k]));
  }
  CHECK(peak == Approx(800.0).epsilon(1.0 / 256.0));
  CHECK(g.rotor_rad_s.back() == 0.0);  // braked to rest before the landing
  // 2 to 2.5 ms behind (delay, then held up to a frame): about 10 rad/s on the spin-up's
  // 4000 rad/s², 20 rad/s on the brake's 8000 rad/s², plus the quantisation (≤ 3 rad/s).
  CHECK(worst_lag > 15.0);
  CHECK(worst_lag < 24.0);
  // The CSV has the column; the body file the rotor.
  CHECK(aloft::test::imu_csv_text(g).rfind("t,gx,gy,gz,ax,ay,az,rotor_rad_s\n", 0) == 0);
  const std::string body = aloft::test::body_json_text(spec.tensor_kg_m2, {}, spec.rotor);
  CHECK(body.find("\"rotor\": {\"inertia_kg_m2\": 2e-05, \"axis\": [0, 0, 1]}") != std::string::npos);
}
