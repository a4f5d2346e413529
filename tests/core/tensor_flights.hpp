// Generated flights with known tensors for the tensor estimate
// (aloft/onboard/tensor_estimator.hpp): Euler's equations, with a rotor where there is one
// (aloft/dynamics/euler_equations.hpp's angular_acceleration), integrated by classical RK4
// at fine steps in double, sampled evenly, and read as a flight controller reads its gyro:
// white noise behind a first-order low-pass (the PT1 filter y += dt/(tau + dt) (x - y),
// the signal with it) and quantised. The rotor spins up from rest over spin_up_s
// (smoothstep) and then holds full speed; its speed is read without noise. No heap: the
// same flights run on the bare-metal runner.
#pragma once

#include <cmath>
#include <cstdint>

#include "aloft/dynamics/euler_equations.hpp"
#include "aloft/onboard/tensor_estimator.hpp"

namespace aloft_test {

struct TensorFlightSpec {
  Eigen::Vector3d moments = Eigen::Vector3d(0.0021, 0.0032, 0.0045);  // ascending, kg·m²
  Eigen::Quaterniond axes = Eigen::Quaterniond::Identity();           // principal into body
  Eigen::Vector3d omega0 = Eigen::Vector3d(3.0, 12.0, 4.0);           // body axes, rad/s
  double duration_s = 0.5;
  double rate_hz = 1000.0;
  int substeps = 8;  // RK4 steps per sample
  double rotor_inertia_kg_m2 = 0.0;
  Eigen::Vector3d rotor_axis = Eigen::Vector3d::UnitZ();
  double rotor_full_rad_s = 0.0;
  double rotor_start_s = 0.0;
  double spin_up_s = 0.2;
  double rotor_delay_s = 0.0;  // the speed is read this late (an ESC's telemetry)
  double noise_rad_s = 0.0;    // white noise per sample, before the filter
  double filter_tau_s = 0.0;   // 0: no filter
  double quantum_rad_s = 0.0;
  Eigen::Vector3d gyro_scale = Eigen::Vector3d::Ones();  // each axis reads its rate times this
  unsigned seed = 1;
};

// A flight controller's gyro: 2.8 mdps/√Hz (the ICM-42688-P's datasheet density) and
// quantised to 1/16.4 °/s (its ±2000 °/s range in 16 bits).
constexpr double icm42688p_noise_density_rad_s = 2.8e-3 * 3.14159265358979 / 180.0;
constexpr double icm42688p_quantum_rad_s = (1.0 / 16.4) * 3.14159265358979 / 180.0;

// Normal deviates from a 64-bit LCG by Box-Muller (no <random>: the same bodies run on bare
// metal).
class NormalDeviates {
 public:
  explicit NormalDeviates(std::uint64_t seed) : state_(seed * 0x9e3779b97f4a7c15ull + 1u) {}
  double uniform() {  // in (0, 1)
    state_ = state_ * 6364136223846793005ull + 1442695040888963407ull;
    return (static_cast<double>(state_ >> 11) + 0.5) * (1.0 / 9007199254740992.0);
  }
  double next() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double r = std::sqrt(-2.0 * std::log(uniform())), phi = 6.283185307179586 * uniform();
    spare_ = r * std::sin(phi);
    has_spare_ = true;
    return r * std::cos(phi);
  }

 private:
  std::uint64_t state_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

class TensorFlight {
 public:
  explicit TensorFlight(const TensorFlightSpec& spec) : spec_(spec), omega_(spec.omega0), normal_(spec.seed) {
    (void)aloft::InertiaTensor<double>::make_from_principal(spec.moments, spec.axes, inertia_);
    dt_us_ = static_cast<std::uint32_t>(std::lround(1e6 / spec.rate_hz));
    samples_ = static_cast<int>(std::lround(spec.duration_s * spec.rate_hz)) + 1;
  }

  const aloft::InertiaTensor<double>& inertia() const { return inertia_; }
  std::uint32_t dt_us() const { return dt_us_; }
  int samples() const { return samples_; }

  // The next sample's gyro reading and rotor speed; false after the last.
  bool next(Eigen::Vector3d& gyro, double& rotor_speed) {
    if (sample_ >= samples_) return false;
    const double dt = dt_us_ * 1e-6;
    if (sample_ > 0) advance(dt);
    Eigen::Vector3d x = spec_.gyro_scale.cwiseProduct(omega_);
    if (spec_.noise_rad_s > 0)
      x += spec_.noise_rad_s * Eigen::Vector3d(normal_.next(), normal_.next(), normal_.next());
    if (sample_ == 0 || spec_.filter_tau_s <= 0) {
      filtered_ = x;
    } else {
      filtered_ += dt / (spec_.filter_tau_s + dt) * (x - filtered_);
    }
    gyro = filtered_;
    if (spec_.quantum_rad_s > 0)
      for (int i = 0; i < 3; ++i) gyro(i) = spec_.quantum_rad_s * std::round(gyro(i) / spec_.quantum_rad_s);
    rotor_speed = speed(t_ - spec_.rotor_delay_s);
    ++sample_;
    return true;
  }

 private:
  double speed(double t) const {
    const double u = (t - spec_.rotor_start_s) / spec_.spin_up_s;
    if (spec_.rotor_inertia_kg_m2 <= 0 || u <= 0) return 0;
    return u >= 1 ? spec_.rotor_full_rad_s : spec_.rotor_full_rad_s * u * u * (3 - 2 * u);
  }
  double speed_rate(double t) const {
    const double u = (t - spec_.rotor_start_s) / spec_.spin_up_s;
    if (spec_.rotor_inertia_kg_m2 <= 0 || u <= 0 || u >= 1) return 0;
    return spec_.rotor_full_rad_s * 6 * u * (1 - u) / spec_.spin_up_s;
  }
  Eigen::Vector3d rate_of(const Eigen::Vector3d& w, double t) const {
    const double j = spec_.rotor_inertia_kg_m2;
    return aloft::angular_acceleration(inertia_, w, Eigen::Vector3d(j * speed(t) * spec_.rotor_axis),
                                       Eigen::Vector3d(j * speed_rate(t) * spec_.rotor_axis));
  }
  void advance(double dt) {
    const double h = dt / spec_.substeps;
    for (int i = 0; i < spec_.substeps; ++i) {
      const Eigen::Vector3d k1 = rate_of(omega_, t_);
      const Eigen::Vector3d k2 = rate_of(omega_ + 0.5 * h * k1, t_ + 0.5 * h);
      const Eigen::Vector3d k3 = rate_of(omega_ + 0.5 * h * k2, t_ + 0.5 * h);
      const Eigen::Vector3d k4 = rate_of(omega_ + h * k3, t_ + h);
      omega_ += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      t_ += h;
    }
  }

  TensorFlightSpec spec_;
  aloft::InertiaTensor<double> inertia_;
  Eigen::Vector3d omega_;
  Eigen::Vector3d filtered_ = Eigen::Vector3d::Zero();
  double t_ = 0;
  std::uint32_t dt_us_ = 1000;
  int samples_ = 0;
  int sample_ = 0;
  NormalDeviates normal_;
};

// The flight through a TensorEstimator<S> whose nominal tensor is `nominal` (body axes).
template <typename S>
aloft::TensorEstimate<S> estimate_flight(const TensorFlightSpec& spec,
                                         const aloft::TensorEstimatorSettings<S>& settings,
                                         const aloft::Rotor<S>& rotor, const Eigen::Matrix3d& nominal) {
  aloft::InertiaTensor<S> nominal_tensor;
  (void)aloft::InertiaTensor<S>::make_from_tensor(nominal.cast<S>(), nominal_tensor);
  aloft::TensorEstimator<S> estimator;
  const aloft::TensorEstimatorInputs<S> inputs{settings, nominal_tensor, rotor};
  estimator.start();
  TensorFlight flight(spec);
  Eigen::Vector3d gyro;
  aloft::Vec3<S> before = aloft::Vec3<S>::Zero();
  double speed = 0;
  bool first = true;
  while (flight.next(gyro, speed)) {
    const aloft::Vec3<S> w = gyro.cast<S>();
    estimator.add(w, before, static_cast<S>(speed), first ? 0u : flight.dt_us(), inputs);
    before = w;
    first = false;
  }
  aloft::TensorEstimate<S> estimate;
  estimator.finish(inputs, estimate);
  return estimate;
}

// The largest angle between an estimated principal axis and the true one, radians.
template <typename S>
double worst_axis_angle(const aloft::TensorEstimate<S>& e, const Eigen::Quaterniond& truth) {
  const Eigen::Matrix3d a = e.axes.template cast<double>().toRotationMatrix(), b = truth.toRotationMatrix();
  double worst = 0;
  for (int i = 0; i < 3; ++i)
    worst = std::fmax(worst, std::acos(std::fmin(1.0, std::fabs(a.col(i).dot(b.col(i))))));
  return worst;
}

}  // namespace aloft_test
