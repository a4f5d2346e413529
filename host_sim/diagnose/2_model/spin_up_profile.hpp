// The speed profile of a rotor a motor spins up (effects/internal_momentum_spin_up.cpp), in
// one place for the walk, the start read off the readings and the report: h(t) = h_inf s(t),
// s the response of a first-order speed loop (time constant tau) to a set-point that ramps
// from 0 at the motor's start t0 to 1 over a rise R, then holds:
//   tau ds/dt = r - s,  r(u) = min(u / R, 1),  u = t - t0,  s = 0 before t0;
//   u <= R:  s = (u - tau (1 - exp(-u / tau))) / R,           ds/dt = (1 - exp(-u / tau)) / R
//   u >  R:  s = 1 - exp(-(u - R) / tau) tau (1 - exp(-R / tau)) / R,
//            ds/dt = exp(-(u - R) / tau) (1 - exp(-R / tau)) / R.
// R = 0 is the first-order step s = 1 - exp(-u / tau) (a speed loop's response); tau -> 0 the
// ramp s = u / R (a motor at its current limit: constant torque until it reaches speed).
//
// theta's layout (I_nom^-1 h_inf [3], rad/s: the body rate that would carry the wheel's final
// momentum; t0 / kSpinUpStartUnit_s, the motor's start after the flight's first sample;
// ln(tau / kSpinUpTimeConstantUnit_s); ln(R / kSpinUpTimeConstantUnit_s)), each scaled so
// that a unit change moves the readings by about a rad/s or less. Both shapes are limits of
// the logarithms (R or tau -> 0), which a fit approaches until the readings no longer move.
// (The ramp's middle t0 + R / 2 in place of t0, tried to decouple a short ramp's start from
// its length, halved the largest held-out error difference between two libms' last bits,
// 2.75e-5 -> 1.29e-5, not more: the fits' R agree to 1e-7 either way; not taken.)
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace aloft::host::diagnose {

constexpr int kSpinUpParameters = 6;
constexpr double kSpinUpStartUnit_s = 0.1;
constexpr double kSpinUpTimeConstantUnit_s = 0.05;

struct SpinUpProfile {
  double start_s = 0.0;  // t0: after the flight's first sample (or on a walk's clock)
  double time_constant_s = 0.05;
  double rise_s = 0.0;  // R: 0, a first-order step

  // s at `since_start_s` = t - t0 (0 before the start).
  double level(double since_start_s) const {
    const double u = since_start_s, tau = time_constant_s;
    if (u <= 0.0) return 0.0;
    if (!(rise_s > 0.0)) return 1.0 - std::exp(-u / tau);
    if (u <= rise_s) return (u + tau * std::expm1(-u / tau)) / rise_s;
    return 1.0 - std::exp(-(u - rise_s) / tau) * tau * -std::expm1(-rise_s / tau) / rise_s;
  }
  // ds/dt at `since_start_s` (0 before the start; at it, the side after).
  double slope(double since_start_s) const {
    const double u = since_start_s, tau = time_constant_s;
    if (u < 0.0) return 0.0;
    if (!(rise_s > 0.0)) return std::exp(-u / tau) / tau;
    if (u <= rise_s) return -std::expm1(-u / tau) / rise_s;
    return std::exp(-(u - rise_s) / tau) * -std::expm1(-rise_s / tau) / rise_s;
  }
  // Whether s is within 1e-6 of 1 at the flight's first sample (start_s <= 0 after it): the
  // readings then see a steady rotor, not the spin-up, and its timing is not measured.
  bool at_speed_before_data() const { return start_s + rise_s <= -std::log(1e6) * time_constant_s; }
  // How long the rise takes, tau for a step and R for a ramp: what tells a motor from a knock.
  double rise_time_s() const { return rise_s + time_constant_s; }
};

// The profile theta's entries 3-5 hold (the layout above), and the reverse.
inline SpinUpProfile spin_up_profile_of(const Eigen::VectorXd& theta) {
  SpinUpProfile profile;
  profile.time_constant_s = kSpinUpTimeConstantUnit_s * std::exp(theta(4));
  profile.rise_s = kSpinUpTimeConstantUnit_s * std::exp(theta(5));
  profile.start_s = kSpinUpStartUnit_s * theta(3);
  return profile;
}
inline void write_spin_up_profile(const SpinUpProfile& profile, Eigen::VectorXd& theta) {
  theta(3) = profile.start_s / kSpinUpStartUnit_s;
  theta(4) = std::log(profile.time_constant_s / kSpinUpTimeConstantUnit_s);
  theta(5) = std::log(profile.rise_s / kSpinUpTimeConstantUnit_s);
}

}  // namespace aloft::host::diagnose
