// aloft's polynomial atan2 (aloft/lanes/lane_angle.hpp) and the principal-frame dynamics
// (aloft/dynamics/principal_dynamics.hpp) against the C library and the body-axes equations.
#include <cmath>
#include <cstdint>

#include "aloft/dynamics/deviation.hpp"
#include "aloft/dynamics/euler_equations.hpp"
#include "aloft/lanes/lane_angle.hpp"
#include "test_api.hpp"

namespace {

using aloft::Vec3;

// A small deterministic generator (no <random>: the same body runs on bare metal).
struct Lcg {
  std::uint64_t state = 0x9e3779b97f4a7c15ull;
  double uniform() {  // in [-1, 1)
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(state >> 11) * (2.0 / 9007199254740992.0) - 1.0;
  }
};

// Largest |nonnegative_atan2(y, x) - atan2(y, x)| over every octant, angles near 0,
// pi/8, pi/4, pi/2 and pi, and random magnitudes over 12 decades.
template <typename S>
S worst_atan2_error() {
  S worst = S(0);
  const auto check = [&](S y, S x) {
    const S err = std::abs(aloft::nonnegative_atan2(y, x) - std::atan2(y, x));
    if (!(err <= worst)) worst = err;
  };
  Lcg random;
  for (int i = 0; i < 20000; ++i) {
    const S scale = static_cast<S>(std::pow(10.0, 6.0 * random.uniform()));
    check(static_cast<S>(std::abs(random.uniform())) * scale, static_cast<S>(random.uniform()) * scale);
  }
  const S angles[] = {S(1e-30),        S(1e-12), S(1e-6),    S(0.3926990817), S(0.7853981634),
                      S(1.5707963268), S(2.0),   S(3.14159), S(3.1415926)};
  for (S a : angles) {
    for (S da = S(-1e-5); da <= S(1e-5); da += S(1e-6)) {
      const S angle = a + da;
      if (angle > S(0) && angle < S(3.14159265)) check(std::sin(angle), std::cos(angle));
    }
  }
  check(S(0), S(1));
  check(S(0), S(-1));
  check(S(1), S(0));
  return worst;
}

// Body-rate RK4 in principal axes (what every integrator now does: into the principal
// frame once, out once per sample) against RK4 on the body-axes equations with the full
// tensor, for a tensor whose axes are off the body's. Relative difference of the rates.
template <typename S>
S worst_frame_difference() {
  aloft::InertiaTensor<S> inertia;
  ALOFT_REQUIRE(aloft::InertiaTensor<S>::make_from_principal(
                    Vec3<S>(S(0.011), S(0.019), S(0.027)),
                    aloft::quat_wxyz(S(0.8), S(0.2), S(-0.5), S(0.26)).normalized(),
                    inertia) == aloft::Status::ok);
  const aloft::PrincipalFrame<S> frame(inertia);
  Vec3<S> body_path(S(3), S(-7), S(9));
  const Vec3<S> w0 = frame.rate_to_principal(body_path);
  aloft::LaneVec3<S> principal_path{w0.x(), w0.y(), w0.z()};
  const S h = S(1e-3);
  S worst = S(0);
  for (int k = 0; k < 500; ++k) {
    principal_path = aloft::principal_rate_rk4_step(frame.coefficients(), principal_path, h);
    const Vec3<S> k1 = aloft::angular_acceleration(inertia, body_path);
    const Vec3<S> k2 = aloft::angular_acceleration(inertia, Vec3<S>(body_path + S(0.5) * h * k1));
    const Vec3<S> k3 = aloft::angular_acceleration(inertia, Vec3<S>(body_path + S(0.5) * h * k2));
    const Vec3<S> k4 = aloft::angular_acceleration(inertia, Vec3<S>(body_path + h * k3));
    body_path += h / S(6) * (k1 + S(2) * (k2 + k3) + k4);
    const S diff = (frame.rate_to_body(principal_path) - body_path).norm() / body_path.norm();
    if (diff > worst) worst = diff;
  }
  return worst;
}

}  // namespace

ALOFT_TEST_CASE("polynomial atan2 agrees with the C library's", "[deviation][lanes]") {
  // The bound for double is 1e-9 rad; fdlibm's polynomial is good to rounding.
  ALOFT_CHECK(worst_atan2_error<double>() < 1e-15);
  // Float: Cephes' atanf, about 1 ulp of pi plus the polynomial's 1e-7 relative.
  ALOFT_CHECK(worst_atan2_error<float>() < 1e-6f);
  ALOFT_CHECK(!(std::abs(aloft::nonnegative_atan2(0.0, 0.0)) > 0.0));
}

ALOFT_TEST_CASE("deviation angle of nearly parallel and nearly opposite vectors", "[deviation][lanes]") {
  const Vec3<double> a(1.0, 2.0, 3.0);
  const Vec3<double> b = a + Vec3<double>(1e-9, -2e-9, 0.5e-9);
  const double exact = std::atan2(a.cross(b).norm(), a.dot(b));
  ALOFT_CHECK(std::abs(aloft::deviation_angle(a, b) - exact) <= 1e-12 * exact);
  const double opposite = std::atan2(a.cross(-b).norm(), a.dot(-b));
  ALOFT_CHECK(std::abs(aloft::deviation_angle(a, Vec3<double>(-b)) - opposite) < 1e-15);
}

ALOFT_TEST_CASE("principal-frame rates follow the body-axes equations", "[dynamics][lanes]") {
  // Measured 1.7e-15 and 1.1e-6.
  ALOFT_CHECK(worst_frame_difference<double>() < 1e-14);
  ALOFT_CHECK(worst_frame_difference<float>() < 5e-6f);
}
