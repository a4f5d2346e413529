#include "phone_toss_session.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "phone_gyro.hpp"
#include "seeded_random.hpp"

namespace aloft::generator {
namespace {

using Vec3 = Eigen::Vector3d;

constexpr double kStep_s = 0.0002;  // integration and filter grid (5 kHz)
constexpr double kRest_s = 1.5;
constexpr double kSpinUp_s = 0.1;

Vec3 box_moments(double mass, const Vec3& size) {
  const Vec3 sq = size.cwiseAbs2();
  return mass / 12.0 * Vec3(sq.y() + sq.z(), sq.x() + sq.z(), sq.x() + sq.y());
}

// Torque-free Euler equations for a diagonal tensor, one RK4 step.
Vec3 euler_step(const Vec3& w, const Vec3& m, double h) {
  auto f = [&](const Vec3& v) {
    return Vec3((m.y() - m.z()) * v.y() * v.z() / m.x(), (m.z() - m.x()) * v.z() * v.x() / m.y(),
                (m.x() - m.y()) * v.x() * v.y() / m.z());
  };
  const Vec3 k1 = f(w), k2 = f(w + 0.5 * h * k1), k3 = f(w + 0.5 * h * k2), k4 = f(w + h * k3);
  return w + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

// The true body rate of one flight on the fine grid, and its sign changes of w_x.
std::vector<Vec3> fly(const Vec3& w0, const Vec3& moments, double duration, int& flips) {
  std::vector<Vec3> out{w0};
  flips = 0;
  Vec3 w = w0;
  for (double t = kStep_s; t <= duration + 1e-12; t += kStep_s) {
    const Vec3 next = euler_step(w, moments, kStep_s);
    if ((next.x() < 0) != (w.x() < 0)) ++flips;
    w = next;
    out.push_back(w);
  }
  return out;
}

bool x_is_intermediate(const Vec3& m) {
  return (m.y() < m.x() && m.x() < m.z()) || (m.z() < m.x() && m.x() < m.y());
}

host::Body nominal_body(const Vec3& moments) {
  std::ostringstream json;
  json.precision(17);
  json << R"({"name": "phone-shaped box", "mass": 0.25, "inertia": {"principal": [)" << moments.x() << ", "
       << moments.y() << ", " << moments.z() << "]}}";
  return host::parse_body_json(json.str(), "phone_toss_session");
}

}  // namespace

PhoneTossSession generate_phone_toss_session(const PhoneTossSpec& spec, std::uint64_t seed) {
  const Vec3 nominal = box_moments(0.25, Vec3(0.077, 0.153, 0.012));
  Vec3 truth = nominal;
  truth(spec.off_axis) *= spec.moment_factor;
  const double slack = 1e-9 * truth.sum();
  if (truth.x() > truth.y() + truth.z() + slack || truth.y() > truth.x() + truth.z() + slack ||
      truth.z() > truth.x() + truth.y() + slack) {
    throw std::invalid_argument("phone toss: that moment factor breaks the triangle inequality");
  }
  SeededRandom throws(seed), noise(seed ^ 0x9e3779b97f4a7c15ULL);
  PhoneTossSession s;
  s.nominal = nominal_body(nominal);
  s.log.format = "imu_csv";
  s.log.path = "phone_toss_session";
  s.true_moments_xyz = truth;
  s.true_ratios = Vec3(truth / truth.x()).tail<2>();
  const int tosses = spec.tosses > 0 ? spec.tosses : 6 + throws.index(7);

  // The true rate of the whole session on the fine grid: rest, spin-up, flight, rest...
  std::vector<Vec3> rate;
  auto rest = [&](double seconds) {
    for (double t = 0; t < seconds; t += kStep_s) rate.push_back(Vec3::Zero());
  };
  rest(kRest_s);
  for (int i = 0; i < tosses; ++i) {
    const double duration = throws.uniform(0.8, 1.0);
    std::vector<Vec3> flight;
    int flips = 0;
    for (int attempt = 0; attempt < 200; ++attempt) {
      const double spin = throws.signed_uniform(18.0, 30.0);
      const double tilt = throws.uniform(0.002, 0.15) * std::abs(spin);
      const double angle = throws.uniform(0.0, 2.0 * SeededRandom::kPi);
      flight = fly(Vec3(spin, tilt * std::cos(angle), tilt * std::sin(angle)), truth, duration, flips);
      if (!x_is_intermediate(truth) || (flips >= 2 && flips <= 4)) break;
    }
    for (double t = kStep_s; t < kSpinUp_s; t += kStep_s) rate.push_back(flight.front() * (t / kSpinUp_s));
    const double release = static_cast<double>(rate.size()) * kStep_s;
    rate.insert(rate.end(), flight.begin(), flight.end());
    s.segments.push_back({"toss" + std::to_string(i + 1), release, release + duration, "toss about x"});
    s.flips.push_back(flips);
    rest(kRest_s);
  }

  // The gyro: filtered on the fine grid, read at jittered times, noisy and quantised.
  const PhoneGyroSpec gyro{spec.rate_hz, spec.cutoff_hz, spec.noise_rad_s, spec.quantum_rad_s, spec.jitter};
  const host::ImuLog read = read_phone_gyro(rate, kStep_s, gyro, noise);
  s.log.time_s = read.time_s;
  s.log.gyro_rad_s = read.gyro_rad_s;
  return s;
}

}  // namespace aloft::generator
