// A flight controller's first-order gyro low-pass (Betaflight's and INAV's PT1, the
// ICM-42688's UI filter at order 1): y += k (x - y) with k = dt / (RC + dt), RC = 1 / (2 pi fc).
// Its noise falls as 1/f^2 past the cutoff (a Butterworth's as 1/f^4), so neighbouring
// readings stay correlated over fs / (pi fc) samples: 25 at 50 Hz behind a 4 kHz loop.
// The same interface as LowPass (low_pass.hpp), so GyroFilter (gyro_filter.hpp) holds either.
#pragma once

#include <Eigen/Core>

namespace aloft::generator {

class FirstOrderLowPass {
 public:
  using Vec3 = Eigen::Vector3d;

  // cutoff_hz <= 0: passes the input through.
  FirstOrderLowPass(double cutoff_hz, double step_s) {
    if (cutoff_hz <= 0) return;
    const double rc = 1.0 / (2.0 * 3.14159265358979323846 * cutoff_hz);
    k_ = step_s / (rc + step_s);
  }
  // As if the input had held `x` forever (unit gain at rest).
  void settle(const Vec3& x) { y_ = x; }
  Vec3 operator()(const Vec3& x) {
    y_ += k_ * (x - y_);
    return y_;
  }
  // The filter's gain per step (1: no filter): y_k = sum over j of k (1 - k)^j x_(k-j).
  double gain() const { return k_; }

 private:
  double k_ = 1.0;
  Vec3 y_ = Vec3::Zero();
};

}  // namespace aloft::generator
