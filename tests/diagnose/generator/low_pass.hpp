// Causal second-order Butterworth low-pass (bilinear transform) on 3-vectors: what an
// IMU's digital low-pass does to its readings. Shared by the phone-gyro generator and the
// generated throws of the release tests (tests/host/generated_throws.hpp).
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace aloft::generator {

class LowPass {
 public:
  using Vec3 = Eigen::Vector3d;

  // cutoff_hz <= 0: passes the input through.
  LowPass(double cutoff_hz, double step_s) {
    if (cutoff_hz <= 0) return;
    const double k = std::tan(3.14159265358979323846 * cutoff_hz * step_s);
    const double norm = 1.0 / (1.0 + std::sqrt(2.0) * k + k * k);
    b0_ = k * k * norm;
    b1_ = 2.0 * b0_;
    b2_ = b0_;
    a1_ = 2.0 * (k * k - 1.0) * norm;
    a2_ = (1.0 - std::sqrt(2.0) * k + k * k) * norm;
  }
  // As if the input had held `x` forever (unit gain at rest).
  void settle(const Vec3& x) { x1_ = x2_ = y1_ = y2_ = x; }
  Vec3 operator()(const Vec3& x) {
    const Vec3 y = b0_ * x + b1_ * x1_ + b2_ * x2_ - a1_ * y1_ - a2_ * y2_;
    x2_ = x1_;
    x1_ = x;
    y2_ = y1_;
    y1_ = y;
    return y;
  }

 private:
  double b0_ = 1.0, b1_ = 0.0, b2_ = 0.0, a1_ = 0.0, a2_ = 0.0;
  Vec3 x1_ = Vec3::Zero(), x2_ = Vec3::Zero(), y1_ = Vec3::Zero(), y2_ = Vec3::Zero();
};

}  // namespace aloft::generator
