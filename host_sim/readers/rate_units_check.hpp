// An IMU log's units checked from the physics before anything is fitted, so that a log in
// the wrong units is refused with its likely unit named instead of answered wrongly
// (a gyro in °/s once came out as a 58.9° sensor misalignment with a 450 rad/s bias).
// Nothing here judges a number by its size alone: a ball really spins at 200 rad/s.
//
//   - Rates and times: in free flight ω obeys Euler's equations, I ω̇ = (I ω) × ω. Scale
//     the rates by s and ω̇ grows by s², so a gyro in °/s reads as if time ran 57.3 times
//     too slowly, and times in ms as if it ran 1000 times too fast. The one number c in
//     Δω = c ∫ I⁻¹ ((I ω) × ω) dt, fitted over every flight, is 1 in SI units, 1/57.3
//     for °/s and 1/1000 for ms. A wrong tensor moves c far less (0.58-1.21 on every IMU
//     trial of ../shared/data). c is trusted only where Euler's equations explain at
//     least half the change of ω (a body spinning about one principal axis shows no such
//     change, and nothing is said), and only a c within 1.5 times a unit's is refused.
// (The accelerometer's units are checked as the log is read: readers/accel_at_rest.hpp.)
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string>
#include <vector>

#include "common/body_file.hpp"

namespace aloft::host {

// One flight's gyro rates as the check reads them: `aloft diagnose` and `aloft study`
// each fill it from their own flights.
struct RateSeries {
  Eigen::Quaterniond sensor_to_body = Eigen::Quaterniond::Identity();
  std::vector<double> time_s;          // strictly increasing
  std::vector<Eigen::Vector3d> omega;  // measured rate, sensor axes
  std::vector<char> usable;            // 0: left out (e.g. saturated)

  std::size_t size() const { return time_s.size(); }
};

// How the flights' change of ω compares with Euler's equations for the body's tensor.
struct EulerScale {
  double c = 1.0;          // Δω = c · Euler's prediction: 1 in SI units
  double explained = 0.0;  // share of the change of ω that c · prediction explains (R²)
  std::size_t spans = 0;   // spans of samples the fit used
};

EulerScale euler_scale(const std::vector<RateSeries>& flights, const Body& body);

// Throws aloft::host::Error, one line, when the flights' rates or times are off by a
// unit's factor (°/s, ms, µs, both, or converted twice), naming the unit and the option
// that converts it; `source` names the log.
void check_rate_units(const std::vector<RateSeries>& flights, const Body& body, const std::string& source);

}  // namespace aloft::host
