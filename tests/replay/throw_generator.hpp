// Generated throws for the replay tests, with exact answers: a body resting on a table, a
// hand's swing that spins it up, a torque-free flight, an impact, rest again. In flight
// the gyro reads the torque-free solution of Euler's equations for the given tensor, and
// an accelerometer at r (body axes) reads exactly the specific force ω̇ × r + ω × (ω × r).
// Sensor axes are body axes. Samples are evenly spaced at rate_hz from t_start_s; the true
// release is the first flight sample and the true landing the first impact sample.
// With a rotor (rotor_flight.hpp) the flight is the gyrostat's instead, I ω̇ + ω × (I ω + h)
// = −ḣ, the accelerometer reads the same specific force with that ω̇, and every sample
// carries the rotor's speed as the firmware logs it from the ESC's telemetry (rotor_rad_s:
// quantised, delayed, held between frames).
#pragma once

#include <Eigen/Dense>

#include "rotor_flight.hpp"

#include <optional>
#include <string>
#include <vector>

namespace aloft::test {

// The rotor of a throw: its moment about its axis, the axis in body axes, the speed it is
// driven through (profile.start_s counted from the release) and the telemetry that logs it
// (telemetry.first_frame_s counted from the recording's first sample).
struct ThrowRotor {
  double inertia_kg_m2 = 2e-5;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  RotorProfile profile;
  RotorTelemetry telemetry;
};

struct ThrowSpec {
  Eigen::Matrix3d tensor_kg_m2 = Eigen::Vector3d(0.0021, 0.0032, 0.0045).asDiagonal();
  Eigen::Vector3d imu_position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d omega_release_rad_s = Eigen::Vector3d(3.0, 12.0, 4.0);  // body axes
  double rate_hz = 1000.0;
  double t_start_s = 0.0;
  int still_samples = 50;  // on the table before the swing
  int swing_samples = 150;
  int flight_samples = 300;
  int impact_samples = 10;
  int rest_samples = 40;
  double gyro_noise_rad_s = 0.0;  // standard deviations of white noise
  double accel_noise_m_s2 = 0.0;
  unsigned seed = 1;
  std::optional<ThrowRotor> rotor;
};

struct GeneratedThrow {
  std::vector<double> t_s;
  std::vector<Eigen::Vector3d> gyro_rad_s;
  std::vector<Eigen::Vector3d> accel_m_s2;
  double release_s = 0.0;
  double landing_s = 0.0;
  // With a rotor: its speed per sample as logged and as it was, and the total angular
  // momentum R(q) (I ω + h) in world axes at the first and the last flight sample.
  std::vector<double> rotor_rad_s;
  std::vector<double> rotor_true_rad_s;
  Eigen::Vector3d momentum_world_release = Eigen::Vector3d::Zero();
  Eigen::Vector3d momentum_world_landing = Eigen::Vector3d::Zero();
};

GeneratedThrow generate_throw(const ThrowSpec& spec);

// The committed example (examples/throw_imu.csv, examples/throw_body.json, the replay
// firmware's recording): 550 samples at 1 kHz, a body with products of inertia, the
// accelerometer at the centre of mass (r = 0, stated in the body file), light noise.
ThrowSpec example_throw_spec();

// A throw with a reaction wheel (J = 2e-5 kg m^2 about body z, the example throw's
// tensor), 900 flight samples at 1 kHz: the wheel starts 30 ms after the release, ramps to
// 800 rad/s over 0.2 s, holds 0.15 s and brakes over 0.1 s, all in flight; DShot telemetry
// every 0.5 ms, 2 ms late, 7 pole pairs.
ThrowSpec rotor_throw_spec();

// The plain IMU CSV of SPEC §3 (t,gx,gy,gz,ax,ay,az, and rotor_rad_s with a rotor): t to
// the microsecond, values with nine significant digits (a float read back exactly).
std::string imu_csv_text(const GeneratedThrow& g);

// A body file (SPEC §2) with the tensor, imu.position when given and the rotor when given.
std::string body_json_text(const Eigen::Matrix3d& tensor_kg_m2,
                           const std::optional<Eigen::Vector3d>& imu_position_m,
                           const std::optional<ThrowRotor>& rotor = std::nullopt);

}  // namespace aloft::test
