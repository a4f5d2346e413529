#include "phone_gyro.hpp"

#include "low_pass.hpp"

#include <algorithm>
#include <cmath>

namespace aloft::generator {
namespace {

using Vec3 = Eigen::Vector3d;

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
