// One flight as the diagnosis sees it: measured angular velocity at each sample, in
// sensor axes for a gyro (with the body file's sensor->body rotation beside it) or in
// body axes for motion capture, and which samples can be trusted.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace aloft::host::diagnose {

// Contact cut away from a given segment (contact.hpp): the hand before the firmware's
// release, or the catch or ground after its landing.
struct Contact {
  double cut_from_s = 0.0, cut_to_s = 0.0;  // the samples left out
  bool before_release = true;               // false: after the landing
  // The largest specific force at the centre of mass over the cut samples, |a - K r|
  // (aloft/dynamics/free_flight_residual.hpp), with r as the firmware used it: the hand's or the
  // ground's force per unit mass.
  double beyond_rotation_m_s2 = 0.0;
  double at_s = 0.0;  // where that largest force was
};

struct Flight {
  std::string name;        // segment name, or the file name for a single flight
  std::string comment;     // the segment's comment, if any
  bool gyro_input = true;  // false: rates derived from motion capture (no sensor effects)
  // Rates differenced from noisy orientations: their noise is not white (consecutive
  // rates share a pose, correlation -1/2), which the noise floor allows for.
  bool rates_from_differences = false;
  Eigen::Quaterniond sensor_to_body = Eigen::Quaterniond::Identity();
  std::vector<double> time_s;          // as recorded, strictly increasing
  std::vector<Eigen::Vector3d> omega;  // measured rate (sensor axes / body axes)
  std::vector<char> usable;            // 0: left out of every fit (e.g. saturated)
  // The accelerometer's specific force at each sample, sensor axes (m/s²); empty when the
  // log has none. Never fitted: it checks what the gyro's fit proposes (an impulse's blow).
  std::vector<Eigen::Vector3d> accel_m_s2;
  std::optional<Eigen::Vector3d> imu_position_m;  // the body file's, body axes
  // The sensor's noise per axis where its log lies still (rest_periods.hpp); unset when
  // the log has no rest. The noise floor prefers it (noise_floor.hpp).
  std::optional<Eigen::Vector3d> rest_noise;
  // Released from rest (rest_periods.hpp): until this time the gyro's low-pass is still
  // settling from the spin-up, so a jump of the rate there cannot be told from the
  // filter's transient, and no impulse is placed there. -infinity: no such start.
  double settling_until_s = -std::numeric_limits<double>::infinity();
  // Half the variance (s^2) of the impulse response of the gyro's low-pass as the noise floor
  // fitted it (noise_floor.hpp): the readings are the motion delayed by the response's mean
  // and bent by this times its second derivative, to second order. 0: no bend (no low-pass
  // fitted, a Butterworth's, whose bend vanishes, or a knee too near the motion's band for the
  // second order to hold: noise_floor.cpp). Set by diagnose_flight once the noise floor is known
  // (diagnosis.hpp); the prediction bends its readings by it (gyro_filter_bend.hpp).
  double gyro_filter_bend_s2 = 0.0;
  // The body file's rotor's angular momentum at the flight's last sample, from the log's
  // rotor_rad_s (J speed axis, body axes, N·m·s); unset without both. Never in the model:
  // diagnose finds a rotor as `internal_momentum`, and the report sets this beside it.
  std::optional<Eigen::Vector3d> logged_rotor_h_N_m_s;
  // What of the given segment was contact, not flight (empty when nothing was cut).
  std::vector<Contact> contacts;

  std::size_t size() const { return time_s.size(); }
  double start_s() const { return time_s.empty() ? 0.0 : time_s.front(); }
  double end_s() const { return time_s.empty() ? 0.0 : time_s.back(); }
  // Samples per second over the flight (0 for fewer than two samples).
  double rate_hz() const { return size() > 1 ? (size() - 1) / std::max(end_s() - start_s(), 1e-12) : 0.0; }
  // Mean |omega| over the usable samples (rad/s): how fast the data turns, which sets
  // the tolerances of parameters measured against it.
  double mean_speed() const {
    double sum = 0.0;
    int count = 0;
    for (std::size_t k = 0; k < size(); ++k) {
      if (!usable[k]) continue;
      sum += omega[k].norm();
      ++count;
    }
    return count ? sum / count : 0.0;
  }
};

}  // namespace aloft::host::diagnose
