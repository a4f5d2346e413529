#include "throw_generator.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

namespace aloft::test {
namespace {

constexpr double kGravity = 9.80665;
const Eigen::Vector3d kRestingSpecificForce(0.0, 0.0, kGravity);  // +z up on the table

// Torque-free: I ω̇ = -ω × I ω.
Eigen::Vector3d omega_dot(const Eigen::Matrix3d& inertia, const Eigen::Vector3d& w) {
  return inertia.inverse() * (-w.cross(inertia * w));
}

Eigen::Vector3d rk4_step(const Eigen::Matrix3d& inertia, const Eigen::Vector3d& w, double h) {
  const Eigen::Vector3d k1 = omega_dot(inertia, w);
  const Eigen::Vector3d k2 = omega_dot(inertia, w + 0.5 * h * k1);
  const Eigen::Vector3d k3 = omega_dot(inertia, w + 0.5 * h * k2);
  const Eigen::Vector3d k4 = omega_dot(inertia, w + h * k3);
  return w + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

// Gaussian noise from a fixed recipe (Box-Muller on mt19937's 32-bit words), so that the
// same seed gives the same file with any standard library.
class Noise {
 public:
  explicit Noise(unsigned seed) : engine_(seed) {}
  Eigen::Vector3d operator()(double sigma) {
    Eigen::Vector3d v;
    for (int k = 0; k < 3; ++k) v(k) = sigma > 0.0 ? sigma * gaussian() : 0.0;
    return v;
  }

 private:
  double uniform() { return (static_cast<double>(engine_()) + 0.5) / 4294967296.0; }
  double gaussian() { return std::sqrt(-2.0 * std::log(uniform())) * std::cos(2.0 * M_PI * uniform()); }
  std::mt19937 engine_;
};

}  // namespace

// The rotor's profile and telemetry on the recording's clock.
static ThrowRotor on_recording_clock(const ThrowRotor& rotor, double release_s, double t_start_s) {
  ThrowRotor out = rotor;
  out.profile.start_s += release_s;
  out.telemetry.first_frame_s += t_start_s;
  return out;
}

GeneratedThrow generate_throw(const ThrowSpec& spec) {
  GeneratedThrow g;
  Noise noise(spec.seed);
  const double dt = 1.0 / spec.rate_hz;
  const int release = spec.still_samples + spec.swing_samples;
  const int landing = release + spec.flight_samples;
  const int total = landing + spec.impact_samples + spec.rest_samples;
  const Eigen::Vector3d& r = spec.imu_position_m;
  Eigen::Vector3d w = spec.omega_release_rad_s;
  Eigen::Vector3d w_landing = Eigen::Vector3d::Zero();
  const double release_t = spec.t_start_s + release * dt;
  const std::optional<ThrowRotor> rotor =
      spec.rotor ? std::optional<ThrowRotor>(on_recording_clock(*spec.rotor, release_t, spec.t_start_s))
                 : std::nullopt;
  std::optional<RotorFlight> gyrostat;
  if (rotor) gyrostat.emplace(spec.tensor_kg_m2, rotor->inertia_kg_m2, rotor->axis, rotor->profile);
  GyrostatState state;
  state.w = w;
  for (int k = 0; k < total; ++k) {
    const double t = spec.t_start_s + k * dt;
    Eigen::Vector3d gyro = Eigen::Vector3d::Zero(), accel = kRestingSpecificForce;
    if (k >= spec.still_samples && k < release) {  // the hand spins it up and pushes hard
      const double u = double(k - spec.still_samples + 1) / spec.swing_samples;
      gyro = u * spec.omega_release_rad_s;
      accel += Eigen::Vector3d(15.0 + 10.0 * u, 5.0 * u, 4.0 * u);
    } else if (k >= release && k < landing && gyrostat) {  // the gyrostat, sub-stepped at <= 0.1 ms
      if (k > release) gyrostat->advance(t - dt, dt, state);
      w = state.w;
      gyro = w;
      accel = gyrostat->omega_dot(t, w).cross(r) + w.cross(w.cross(r));
      w_landing = w;
      if (k == release) g.momentum_world_release = gyrostat->world_momentum(t, state);
      g.momentum_world_landing = gyrostat->world_momentum(t, state);
    } else if (k >= release && k < landing) {  // torque-free, sub-stepped at <= 0.1 ms
      if (k > release) {
        const int steps = int(std::ceil(dt / 1e-4));
        for (int s = 0; s < steps; ++s) w = rk4_step(spec.tensor_kg_m2, w, dt / steps);
      }
      gyro = w;
      accel = omega_dot(spec.tensor_kg_m2, w).cross(r) + w.cross(w.cross(r));
      w_landing = w;
    } else if (k >= landing && k < landing + spec.impact_samples) {  // stopped hard
      const double u = 1.0 - double(k - landing + 1) / spec.impact_samples;
      gyro = u * w_landing;
      accel = Eigen::Vector3d(40.0, -30.0, 60.0) * (0.5 + u);
    }
    g.t_s.push_back(t);
    g.gyro_rad_s.push_back(gyro + noise(spec.gyro_noise_rad_s));
    g.accel_m_s2.push_back(accel + noise(spec.accel_noise_m_s2));
    if (rotor) {
      g.rotor_rad_s.push_back(rotor->telemetry.logged(t, rotor->profile));
      g.rotor_true_rad_s.push_back(rotor->profile.speed(t));
    }
  }
  g.release_s = g.t_s[std::size_t(release)];
  g.landing_s = g.t_s[std::size_t(landing)];
  return g;
}

ThrowSpec example_throw_spec() {
  ThrowSpec spec;
  spec.tensor_kg_m2 << 0.0021, 0.0001, 0.0, 0.0001, 0.0032, 0.00005, 0.0, 0.00005, 0.0045;
  spec.gyro_noise_rad_s = 0.002;
  spec.accel_noise_m_s2 = 0.02;
  return spec;
}

ThrowSpec rotor_throw_spec() {
  ThrowSpec spec = example_throw_spec();
  spec.flight_samples = 900;
  ThrowRotor rotor;
  rotor.inertia_kg_m2 = 2e-5;
  rotor.axis = Eigen::Vector3d::UnitZ();
  rotor.profile.start_s = 0.03;
  rotor.profile.spin_up_s = 0.2;
  rotor.profile.full_rad_s = 800.0;
  rotor.profile.hold_s = 0.15;
  rotor.profile.brake_s = 0.1;
  rotor.telemetry.period_s = 0.0005;
  rotor.telemetry.delay_s = 0.002;
  spec.rotor = rotor;
  return spec;
}

std::string imu_csv_text(const GeneratedThrow& g) {
  const bool rotor = !g.rotor_rad_s.empty();
  std::string text = rotor ? "t,gx,gy,gz,ax,ay,az,rotor_rad_s\n" : "t,gx,gy,gz,ax,ay,az\n";
  char row[256];
  for (std::size_t i = 0; i < g.t_s.size(); ++i) {
    const Eigen::Vector3d& w = g.gyro_rad_s[i];
    const Eigen::Vector3d& a = g.accel_m_s2[i];
    std::snprintf(row, sizeof row, "%.6f,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g", g.t_s[i], w.x(), w.y(), w.z(), a.x(),
                  a.y(), a.z());
    text += row;
    if (rotor) {
      std::snprintf(row, sizeof row, ",%.9g", g.rotor_rad_s[i]);
      text += row;
    }
    text += '\n';
  }
  return text;
}

std::string body_json_text(const Eigen::Matrix3d& t, const std::optional<Eigen::Vector3d>& imu_position_m,
                           const std::optional<ThrowRotor>& rotor) {
  char text[512];
  std::snprintf(text, sizeof text,
                "{\"name\": \"generated throw\", \"mass\": 0.5,\n"
                " \"inertia\": {\"tensor\": [[%.9g, %.9g, %.9g], [%.9g, %.9g, %.9g], [%.9g, %.9g, %.9g]]}",
                t(0, 0), t(0, 1), t(0, 2), t(1, 0), t(1, 1), t(1, 2), t(2, 0), t(2, 1), t(2, 2));
  std::string json = text;
  if (imu_position_m) {
    std::snprintf(text, sizeof text, ",\n \"imu\": {\"position\": [%.9g, %.9g, %.9g]}", imu_position_m->x(),
                  imu_position_m->y(), imu_position_m->z());
    json += text;
  }
  if (rotor) {
    std::snprintf(text, sizeof text, ",\n \"rotor\": {\"inertia_kg_m2\": %.9g, \"axis\": [%.9g, %.9g, %.9g]}",
                  rotor->inertia_kg_m2, rotor->axis.x(), rotor->axis.y(), rotor->axis.z());
    json += text;
  }
  return json + "}\n";
}

}  // namespace aloft::test
