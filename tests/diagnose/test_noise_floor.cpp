// diagnose/noise_floor: a known sigma in, the same sigma out, whatever smooth motion the
// noise rides on.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "diagnose/4_judge/noise_floor.hpp"

using namespace aloft::host::diagnose;

namespace {

// 2 s at 1 kHz of a smooth rate (a few rad/s, turning at about 1 Hz) plus noise.
Flight noisy_flight(const Eigen::Vector3d& sigma, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  Flight f;
  for (int k = 0; k < 2000; ++k) {
    const double t = 0.001 * k;
    const Eigen::Vector3d smooth(3.0 * std::cos(6.0 * t), 2.0 * std::sin(6.0 * t), 8.0 + t);
    f.time_s.push_back(t);
    f.omega.push_back(
        smooth + Eigen::Vector3d(sigma(0) * unit(random), sigma(1) * unit(random), sigma(2) * unit(random)));
    f.usable.push_back(1);
  }
  return f;
}

}  // namespace

TEST_CASE("estimate_noise_floor returns the white noise's sigma per axis", "[noise_floor]") {
  const Eigen::Vector3d sigma(0.01, 0.02, 0.05);
  const NoiseFloor floor = estimate_noise_floor(noisy_flight(sigma, 3));
  CHECK(floor.reliable);
  for (int a = 0; a < 3; ++a) CHECK(floor.sigma(a) == Approx(sigma(a)).epsilon(0.1));
}

TEST_CASE("estimate_noise_floor allows for rates differenced from noisy poses", "[noise_floor]") {
  // Rates e_k = (n_k+1 - n_k) / dt from pose noise n of sigma s: each rate has sigma
  // s sqrt(2) / dt, but neighbours are correlated; the estimate must still be that sigma.
  std::mt19937 random(11);
  const double s = 1e-4, dt = 0.004;
  std::normal_distribution<double> pose_noise(0.0, s);
  Flight f;
  f.rates_from_differences = true;
  Eigen::Vector3d previous(pose_noise(random), pose_noise(random), pose_noise(random));
  for (int k = 0; k < 1500; ++k) {
    const Eigen::Vector3d next(pose_noise(random), pose_noise(random), pose_noise(random));
    f.time_s.push_back(dt * k);
    f.omega.push_back(Eigen::Vector3d(5.0, 1.0, -2.0) + (next - previous) / dt);
    f.usable.push_back(1);
    previous = next;
  }
  const NoiseFloor floor = estimate_noise_floor(f);
  for (int a = 0; a < 3; ++a) CHECK(floor.sigma(a) == Approx(s * std::sqrt(2.0) / dt).epsilon(0.1));
}

TEST_CASE("estimate_noise_floor is not inflated by a time gap or unusable samples", "[noise_floor]") {
  const Eigen::Vector3d sigma(0.02, 0.02, 0.02);
  Flight f = noisy_flight(sigma, 5);
  for (std::size_t k = 1000; k < f.size(); ++k) f.time_s[k] += 0.5;                   // 0.5 s of samples lost
  for (std::size_t k = 300; k < 310; ++k) f.omega[k] += Eigen::Vector3d(50, 50, 50);  // glitch
  for (std::size_t k = 300; k < 310; ++k) f.usable[k] = 0;
  const NoiseFloor floor = estimate_noise_floor(f);
  for (int a = 0; a < 3; ++a) CHECK(floor.sigma(a) == Approx(sigma(a)).epsilon(0.1));
}
