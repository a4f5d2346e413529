// A rotor inside the body that a motor spins up from rest after release: a reaction wheel
// or a propeller started a few tens of milliseconds into the flight, whose speed rises
// towards its final value as a first-order step, s(u) = 1 - exp(-u / tau) for u = t - t0 >= 0
// (0 before). Its angular momentum relative to the body, fixed along a body axis, is
// h(t) = h_final s(t - t0); the body feels -w x h and the motor's reaction torque -dh/dt:
// I dw/dt + w x (I w + h) = -dh/dt (SPEC §2, `rotor`; §4, internal_momentum).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace aloft::generator {

struct RotorSpinUp {
  Eigen::Vector3d final_momentum_N_m_s = Eigen::Vector3d::Zero();  // h as t -> infinity, body axes
  double start_s = 0.0;                                            // t0, from release
  double time_constant_s = 0.05;                                   // tau

  bool present() const { return final_momentum_N_m_s.squaredNorm() > 0.0; }
  // s(t - t0) and its rate of change. The rate steps from 0 to 1 / tau at t0: an
  // integrator's step that ends or starts there asks for the side it lies on (`running`:
  // the motor has started within this step's span), or it is taken by t alone.
  double fraction(double t) const {
    return t <= start_s ? 0.0 : 1.0 - std::exp(-(t - start_s) / time_constant_s);
  }
  double fraction_rate(double t, bool running) const {
    return running ? std::exp(-std::max(t - start_s, 0.0) / time_constant_s) / time_constant_s : 0.0;
  }
  double fraction_rate(double t) const { return fraction_rate(t, t > start_s); }
  Eigen::Vector3d momentum(double t) const { return fraction(t) * final_momentum_N_m_s; }
  Eigen::Vector3d momentum_rate(double t, bool running) const {
    return fraction_rate(t, running) * final_momentum_N_m_s;
  }
  Eigen::Vector3d momentum_rate(double t) const { return fraction_rate(t) * final_momentum_N_m_s; }
};

}  // namespace aloft::generator
