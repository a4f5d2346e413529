// The gyro's digital low-pass as FlightSpec asks for it: none, a second-order Butterworth
// (a MEMS gyro's DLPF, a phone's; low_pass.hpp) or first-order PT1 stages in series (a
// flight controller's: one, Betaflight's default; two at one cutoff, its PT2; a second at
// twice the first's cutoff, its default pair of gyro low-passes; first_order_low_pass.hpp).
// Each acts on signal and noise alike.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "first_order_low_pass.hpp"
#include "low_pass.hpp"

namespace aloft::generator {

class GyroFilter {
 public:
  using Vec3 = Eigen::Vector3d;

  // order 1: `stages` PT1s, the first at cutoff_hz, each later one at later_ratio times it;
  // any other order: the second-order Butterworth. cutoff_hz <= 0: none.
  GyroFilter(int order, double cutoff_hz, double step_s, int stages = 1, double later_ratio = 1.0)
      : first_order_(order == 1), second_(cutoff_hz, step_s) {
    for (int k = 0; first_order_ && k < stages; ++k)
      stages_.emplace_back(k == 0 ? cutoff_hz : later_ratio * cutoff_hz, step_s);
  }
  void settle(const Vec3& x) {
    if (!first_order_) return second_.settle(x);
    for (FirstOrderLowPass& stage : stages_) stage.settle(x);
  }
  Vec3 operator()(const Vec3& x) {
    if (!first_order_) return second_(x);
    Vec3 y = x;
    for (FirstOrderLowPass& stage : stages_) y = stage(y);
    return y;
  }

 private:
  bool first_order_;
  std::vector<FirstOrderLowPass> stages_;
  LowPass second_;
};

}  // namespace aloft::generator
