#include "phone_gyro.hpp"

#include <algorithm>
#include <cmath>

namespace aloft::generator {
namespace {

using Vec3 = Eigen::Vector3d;

// Causal second-order Butterworth low-pass (bilinear transform), one axis at a time.
class LowPass {
 public:
  LowPass(double cutoff_hz, double step_s) {
    if (cutoff_hz <= 0) return;
    const double k = std::tan(SeededRandom::kPi * cutoff_hz * step_s);
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

}  // namespace

host::ImuLog read_phone_gyro(const std::vector<Vec3>& fine, double step_s, const PhoneGyroSpec& spec,
                             SeededRandom& noise) {
  host::ImuLog log;
  log.format = "imu_csv";
  if (fine.empty()) return log;
  // The filter starts settled on the first reading (the phone has been lying there).
  LowPass filter(spec.cutoff_hz, step_s);
  filter.settle(fine.front());
  std::vector<Vec3> filtered;
  filtered.reserve(fine.size());
  for (const Vec3& w : fine) filtered.push_back(filter(w));
  const double end = static_cast<double>(filtered.size() - 1) * step_s;
  for (double t = 0.0; t < end; t += (1.0 + noise.uniform(-spec.jitter, spec.jitter)) / spec.rate_hz) {
    const double index = t / step_s;
    const std::size_t k = static_cast<std::size_t>(index);
    const double f = index - static_cast<double>(k);
    Vec3 w = (1.0 - f) * filtered[k] + f * filtered[std::min(k + 1, filtered.size() - 1)];
    w += noise.normal_vector(spec.noise_rad_s);
    if (spec.quantum_rad_s > 0) w = (w / spec.quantum_rad_s).array().round().matrix() * spec.quantum_rad_s;
    log.time_s.push_back(t);
    log.gyro_rad_s.push_back(w);
  }
  return log;
}

}  // namespace aloft::generator
