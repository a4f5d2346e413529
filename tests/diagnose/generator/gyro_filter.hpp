// The gyro's digital low-pass as FlightSpec asks for it: none, a second-order Butterworth
// (a MEMS gyro's DLPF, a phone's; low_pass.hpp) or a first-order PT1 (a flight
// controller's default; first_order_low_pass.hpp). Both act on signal and noise alike.
#pragma once

#include <Eigen/Core>

#include "first_order_low_pass.hpp"
#include "low_pass.hpp"

namespace aloft::generator {

class GyroFilter {
 public:
  using Vec3 = Eigen::Vector3d;

  // order 1: PT1; any other order: the second-order Butterworth. cutoff_hz <= 0: none.
  GyroFilter(int order, double cutoff_hz, double step_s)
      : first_order_(order == 1), first_(cutoff_hz, step_s), second_(cutoff_hz, step_s) {}
  void settle(const Vec3& x) { first_order_ ? first_.settle(x) : second_.settle(x); }
  Vec3 operator()(const Vec3& x) { return first_order_ ? first_(x) : second_(x); }

 private:
  bool first_order_;
  FirstOrderLowPass first_;
  LowPass second_;
};

}  // namespace aloft::generator
