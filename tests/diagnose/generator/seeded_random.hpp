// The generator's only source of randomness. std::mt19937_64's output sequence is fixed
// by the C++ standard, but std::uniform_real_distribution and std::normal_distribution
// are not (libstdc++ and libc++ give different numbers for the same seed), so the
// distributions are written here by hand: a flight is then the same on every platform
// for the same seed, which the withheld-effect test relies on.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <random>

namespace aloft::generator {

class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1): the top 53 bits of one 64-bit draw.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  double uniform(double low, double high) { return low + (high - low) * uniform(); }

  // Uniform magnitude in [low, high] with a random sign.
  double signed_uniform(double low, double high) {
    const double magnitude = uniform(low, high);
    return uniform() < 0.5 ? -magnitude : magnitude;
  }

  // Integer uniform in [0, n).
  int index(int n) { return static_cast<int>(uniform() * n); }

  // Standard normal by Box-Muller (both values used, so no draw is wasted).
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - uniform();  // in (0, 1]: log is finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * kPi * u2;
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }

  Eigen::Vector3d normal_vector(double sigma) {
    const double x = normal();
    const double y = normal();
    const double z = normal();
    return sigma * Eigen::Vector3d(x, y, z);
  }

  // Uniform on the unit sphere (normalised Gaussian vector).
  Eigen::Vector3d unit_vector() {
    Eigen::Vector3d v;
    do {
      v = normal_vector(1.0);
    } while (v.norm() < 1e-9);
    return v.normalized();
  }

  // A rotation by exactly `angle_rad` about a uniformly random axis.
  Eigen::Quaterniond rotation_by(double angle_rad) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle_rad, unit_vector()));
  }

  static constexpr double kPi = 3.14159265358979323846;

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace aloft::generator
