// The generators' rotor (SPEC §2 `rotor`): a wheel, fan or motor inside the body whose
// speed the flight's firmware logs, as the replay and release-detection throws carry it.
// A separate code path from lib/, so that the estimator is checked against physics it
// did not write.
//   - RotorProfile: the speed a motor controller drives it through in one flight: at rest
//     until start_s, a spin-up from rest (a ramp to full speed over spin_up_s, or a
//     first-order rise with time constant spin_up_s / 3, 95 % at spin_up_s), held at full
//     speed for hold_s (the pulse), then braked to rest at a constant rate over brake_s
//     (from full speed; less from a first-order rise that has not reached it).
//   - RotorFlight: the body with that rotor in free flight, the gyrostat of SPEC §2:
//     I ω̇ + ω × (I ω + h) = −ḣ, h = J · speed(t) · axis (body axes), dq/dt = ½ q ⊗ (0, ω);
//     classical RK4 on (q, ω) with steps no longer than max_step_s and step boundaries on
//     every corner of the profile (where ḣ jumps), so each step sees a smooth right-hand
//     side. R(q) (I ω + h) is then constant: world_momentum() is what the tests check.
//   - RotorTelemetry: the speed as a firmware logs it from an ESC's DShot bidirectional
//     telemetry: a frame every period_s, each reporting the speed of delay_s before it
//     arrives as an electrical period in whole microseconds packed into a 9-bit mantissa
//     and a 3-bit shift (so truncated to 9 significant bits), read back as
//     eRPM = 60e6 / period and divided by the motor's pole pairs; a period beyond the
//     largest code (511 << 7 = 65,408 µs) reads as stopped. The firmware knows the sign
//     from the direction it commands. Between frames the last value is held.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace aloft::test {

struct RotorProfile {
  double start_s = 0.0;  // spin-up starts (the recording's clock)
  double spin_up_s = 0.2;
  bool first_order = false;   // false: a ramp
  double full_rad_s = 600.0;  // signed: a positive speed turns right-handed about the axis
  double hold_s = 0.1;
  double brake_s = 0.1;  // from full speed to rest

  double brake_start_s() const { return start_s + spin_up_s + hold_s; }
  double tau_s() const { return spin_up_s / 3.0; }
  // The speed as the spin-up leaves it at t (before any braking).
  double driven(double t) const {
    const double s = t - start_s;
    if (s <= 0.0) return 0.0;
    if (first_order) return full_rad_s * -std::expm1(-s / tau_s());
    return s < spin_up_s ? full_rad_s * s / spin_up_s : full_rad_s;
  }
  // The spin-up's acceleration at t on the piece that holds `piece` (the formula of that
  // piece, so that a step ending on a corner keeps its own piece's value there).
  double driven_rate(double t, double piece) const {
    const double s = piece - start_s;
    if (s < 0.0) return 0.0;
    if (first_order) return full_rad_s / tau_s() * std::exp(-(t - start_s) / tau_s());
    return s < spin_up_s ? full_rad_s / spin_up_s : 0.0;
  }
  double brake_rate() const { return full_rad_s / brake_s; }  // signed, as the speed
  double stop_s() const { return brake_start_s() + driven(brake_start_s()) / brake_rate(); }
  double speed(double t) const {
    if (t < brake_start_s()) return driven(t);
    return t < stop_s() ? driven(brake_start_s()) - brake_rate() * (t - brake_start_s()) : 0.0;
  }
  // d speed / dt at t, by the formula of the piece between corners that holds `piece`
  // (by default t's own: right-continuous at the corners).
  double acceleration(double t, double piece) const {
    if (piece < brake_start_s()) return driven_rate(t, piece);
    return piece < stop_s() ? -brake_rate() : 0.0;
  }
  double acceleration(double t) const { return acceleration(t, t); }
  // Where the acceleration jumps (the ramp's end is no corner of a first-order rise).
  std::array<double, 4> corners() const {
    return {start_s, first_order ? start_s : start_s + spin_up_s, brake_start_s(), stop_s()};
  }
};

struct GyrostatState {
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();  // body -> world
  Eigen::Vector3d w = Eigen::Vector3d::Zero();            // body axes, rad/s
};

class RotorFlight {
 public:
  RotorFlight(const Eigen::Matrix3d& inertia_kg_m2, double rotor_inertia_kg_m2, const Eigen::Vector3d& axis,
              const RotorProfile& profile)
      : inertia_(inertia_kg_m2),
        inverse_(inertia_kg_m2.inverse()),
        rotor_inertia_(rotor_inertia_kg_m2),
        axis_(axis.normalized()),
        profile_(profile) {}

  Eigen::Vector3d h(double t) const { return rotor_inertia_ * profile_.speed(t) * axis_; }
  Eigen::Vector3d h_dot(double t, double piece) const {
    return rotor_inertia_ * profile_.acceleration(t, piece) * axis_;
  }
  // ω̇ at t (on t's own piece of the profile, or on the one holding `piece`).
  Eigen::Vector3d omega_dot(double t, const Eigen::Vector3d& w) const { return omega_dot(t, w, t); }
  Eigen::Vector3d omega_dot(double t, const Eigen::Vector3d& w, double piece) const {
    return inverse_ * (-w.cross(inertia_ * w + h(t)) - h_dot(t, piece));
  }
  // I ω + h turned into world axes: constant in free flight.
  Eigen::Vector3d world_momentum(double t, const GyrostatState& s) const {
    return s.q * (inertia_ * s.w + h(t));
  }

  // From t to t + dt.
  void advance(double t, double dt, GyrostatState& s, double max_step_s = 1e-4) const {
    const double end = t + dt;
    while (t < end) {
      double next = std::min(end, t + max_step_s);
      for (const double c : profile_.corners()) {
        if (c > t && c < next) next = c;
      }
      rk4_step(t, next - t, s);
      t = next;
    }
  }

 private:
  struct Rate {
    Eigen::Vector4d q;  // Eigen's coefficient order x, y, z, w
    Eigen::Vector3d w;
  };
  Rate rate(double t, const Eigen::Vector4d& q, const Eigen::Vector3d& w, double piece) const {
    const Eigen::Quaterniond dq = Eigen::Quaterniond(q) * Eigen::Quaterniond(0.0, w.x(), w.y(), w.z());
    return {0.5 * dq.coeffs(), omega_dot(t, w, piece)};
  }
  // A step never crosses a corner, so every stage takes ḣ from the piece the step lies in
  // (named by its midpoint), also at its ends, where a corner's other piece begins.
  void rk4_step(double t, double h, GyrostatState& s) const {
    const double piece = t + 0.5 * h;
    const Eigen::Vector4d q0 = s.q.coeffs();
    const Rate k1 = rate(t, q0, s.w, piece);
    const Rate k2 = rate(t + 0.5 * h, q0 + 0.5 * h * k1.q, s.w + 0.5 * h * k1.w, piece);
    const Rate k3 = rate(t + 0.5 * h, q0 + 0.5 * h * k2.q, s.w + 0.5 * h * k2.w, piece);
    const Rate k4 = rate(t + h, q0 + h * k3.q, s.w + h * k3.w, piece);
    const Eigen::Vector4d q1 = q0 + h / 6.0 * (k1.q + 2.0 * (k2.q + k3.q) + k4.q);
    s.q = Eigen::Quaterniond(q1).normalized();
    s.w += h / 6.0 * (k1.w + 2.0 * (k2.w + k3.w) + k4.w);
  }

  Eigen::Matrix3d inertia_;
  Eigen::Matrix3d inverse_;
  double rotor_inertia_;
  Eigen::Vector3d axis_;
  RotorProfile profile_;
};

struct RotorTelemetry {
  double period_s = 0.001;
  double delay_s = 0.002;
  double first_frame_s = 0.0;  // the frames' phase
  int pole_pairs = 7;

  static constexpr double kTwoPi = 6.283185307179586;
  // The speed a DShot frame reports for a true speed (rad/s, signed).
  double quantised(double speed_rad_s) const {
    const double erpm = std::abs(speed_rad_s) * 60.0 / kTwoPi * pole_pairs;
    if (!(erpm > 0.0)) return 0.0;
    const double period_us = std::floor(60e6 / erpm);
    if (period_us > 65408.0) return 0.0;  // beyond the largest code: stopped
    unsigned mantissa = static_cast<unsigned>(period_us), shift = 0;
    while (mantissa > 511u) {
      mantissa >>= 1u;
      ++shift;
    }
    const double coded_us = static_cast<double>(mantissa << shift);
    if (coded_us <= 0.0) return 0.0;
    const double read_rad_s = 60e6 / coded_us / pole_pairs * kTwoPi / 60.0;
    return speed_rad_s < 0.0 ? -read_rad_s : read_rad_s;
  }
  // What the firmware holds at time t: the last frame's report (0 before the first).
  double logged(double t, const RotorProfile& profile) const {
    if (t < first_frame_s) return 0.0;
    const double frame = first_frame_s + std::floor((t - first_frame_s) / period_s) * period_s;
    return quantised(profile.speed(frame - delay_s));
  }
};

}  // namespace aloft::test
