// A rotor inside the body that a motor spins up from rest after release: a reaction wheel
// or a propeller started a few tens of milliseconds into the flight. Its angular momentum
// relative to the body, fixed along a body axis, is h(t) = h_final s(t - t0), s(u) = 0 for
// u < 0; the body feels -w x h and the motor's reaction torque -dh/dt:
// I dw/dt + w x (I w + h) = -dh/dt (SPEC §2, `rotor`; §4, internal_momentum). The shape
// s (`SpinUpShape`):
//   - a first-order step, s(u) = 1 - exp(-u / tau): a speed loop's response, the shape
//     diagnose's spin-up model assumes;
//   - over a rise of `rise_s` (v = u / rise_s, s = 1 from v = 1 on), shapes the model does
//     not hold, to see how a fit of the first-order one fares on them:
//     - a ramp, s = v: a motor at its current limit, constant torque until it reaches its
//       speed, then none;
//     - a smooth step, s = 3 v^2 - 2 v^3: torque rising from zero and back (the shape
//       tests/core/tensor_flights.hpp spins its wheels up with).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace aloft::generator {

enum class SpinUpShape { first_order, ramp, smooth_step };
// Each shape's name, in the enum's order (truth files, aloft_generate_flights
// --spin-up-shape, the spin-up test's ALOFT_SPIN_UP_SHAPE).
constexpr const char* kSpinUpShapeNames[] = {"first_order", "ramp", "smooth_step"};
inline const char* spin_up_shape_name(SpinUpShape shape) {
  return kSpinUpShapeNames[static_cast<int>(shape)];
}
// The shape of that name; throws std::invalid_argument for any other.
inline SpinUpShape spin_up_shape_named(const std::string& name) {
  for (int i = 0; i < static_cast<int>(std::size(kSpinUpShapeNames)); ++i) {
    if (name == kSpinUpShapeNames[i]) return static_cast<SpinUpShape>(i);
  }
  throw std::invalid_argument("unknown spin-up shape '" + name + "' (first_order, ramp or smooth_step)");
}

struct RotorSpinUp {
  Eigen::Vector3d final_momentum_N_m_s = Eigen::Vector3d::Zero();  // h as t -> infinity, body axes
  double start_s = 0.0;                                            // t0, from release
  double time_constant_s = 0.05;                                   // tau
  SpinUpShape shape = SpinUpShape::first_order;
  double rise_s = 0.0;  // a ramp's or a smooth step's

  bool present() const { return final_momentum_N_m_s.squaredNorm() > 0.0; }
  double fraction(double t) const {
    const double u = t - start_s;
    if (u <= 0.0) return 0.0;
    if (shape == SpinUpShape::first_order) return 1.0 - std::exp(-u / time_constant_s);
    const double v = std::min(u / rise_s, 1.0);
    return shape == SpinUpShape::ramp ? v : v * v * (3.0 - 2.0 * v);
  }
  // The instants where s's rate of change steps: the motor's start, and a ramp's end (the
  // smooth step's rate is continuous there, its slope is not).
  std::vector<double> rate_steps_s() const {
    std::vector<double> steps;
    if (!present()) return steps;
    if (start_s > 0.0) steps.push_back(start_s);
    if (shape != SpinUpShape::first_order) steps.push_back(start_s + rise_s);
    return steps;
  }
  // ds/dt at t, on the side of the steps that `side_s` lies on: an integrator's step that
  // ends or starts at one asks for the side its middle lies on.
  double fraction_rate(double t, double side_s) const {
    const double u = side_s - start_s;
    if (u <= 0.0) return 0.0;
    if (shape == SpinUpShape::first_order)
      return std::exp(-std::max(t - start_s, 0.0) / time_constant_s) / time_constant_s;
    if (u >= rise_s) return 0.0;
    if (shape == SpinUpShape::ramp) return 1.0 / rise_s;
    const double v = std::clamp((t - start_s) / rise_s, 0.0, 1.0);
    return 6.0 * v * (1.0 - v) / rise_s;
  }
  double fraction_rate(double t) const { return fraction_rate(t, t); }
  Eigen::Vector3d momentum(double t) const { return fraction(t) * final_momentum_N_m_s; }
  Eigen::Vector3d momentum_rate(double t, double side_s) const {
    return fraction_rate(t, side_s) * final_momentum_N_m_s;
  }
  Eigen::Vector3d momentum_rate(double t) const { return fraction_rate(t) * final_momentum_N_m_s; }
};

}  // namespace aloft::generator
