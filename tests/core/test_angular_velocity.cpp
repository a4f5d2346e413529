// Angular velocity from consecutive orientations, in body and world axes.
#include "aloft/dynamics/angular_velocity.hpp"
#include "test_api.hpp"
#include "tolerances.hpp"

namespace {

using aloft::Quat;
using aloft::Status;
using aloft::Vec3;

template <typename S>
void check_constant_rate(S rate_scale) {
  const S tol = aloft_test::Tolerances<S>::rounding;
  const Quat<S> q0 = aloft::quat_wxyz(S(0.7), S(0.1), S(-0.6), S(0.3)).normalized();
  const Vec3<S> omega = Vec3<S>(S(3), S(-1), S(12)) * rate_scale;
  const S dt = S(1e-3);
  const Quat<S> q1 = q0 * aloft::quat_exp(Vec3<S>(omega * dt));
  Vec3<S> body = Vec3<S>::Zero();
  Vec3<S> world = Vec3<S>::Zero();
  ALOFT_REQUIRE(aloft::omega_body_from_orientations(q0, q1, dt, body) == Status::ok);
  ALOFT_REQUIRE(aloft::omega_world_from_orientations(q0, q1, dt, world) == Status::ok);
  // The rate error is the angle's rounding over dt, at every scale of rate (no acos).
  ALOFT_CHECK((body - omega).norm() <= S(10) * tol / dt);
  ALOFT_CHECK((world - q0 * omega).norm() <= S(10) * tol / dt);
}

}  // namespace

ALOFT_TEST_CASE("a constant rate is recovered from two orientations", "[angular-velocity]") {
  for (double scale : {1.0, 1e-3, 1e-6}) {
    check_constant_rate<double>(scale);
  }
  check_constant_rate<float>(1.0f);
}

ALOFT_TEST_CASE("tiny rotations keep full relative precision in double", "[angular-velocity]") {
  const Vec3<double> omega(2e-7, -1e-7, 3e-7);  // rad/s: 3.7e-10 rad per 1 ms step
  const Quat<double> q0 = Quat<double>::Identity();
  const Quat<double> q1 = aloft::quat_exp(Vec3<double>(omega * 1e-3));
  Vec3<double> body = Vec3<double>::Zero();
  ALOFT_REQUIRE(aloft::omega_body_from_orientations(q0, q1, 1e-3, body) == Status::ok);
  ALOFT_CHECK((body - omega).norm() / omega.norm() < 1e-9);
}

ALOFT_TEST_CASE("bad orientations and steps are refused", "[angular-velocity][bad-input]") {
  Vec3<double> out(7.0, 7.0, 7.0);
  const Quat<double> id = Quat<double>::Identity();
  ALOFT_CHECK(aloft::omega_body_from_orientations(id, id, 0.0, out) == Status::non_positive_time_step);
  ALOFT_CHECK(aloft::omega_body_from_orientations(id, id, -1e-3, out) == Status::non_positive_time_step);
  ALOFT_CHECK(aloft::omega_body_from_orientations(id, id, std::nan(""), out) == Status::non_finite_input);
  ALOFT_CHECK(aloft::omega_body_from_orientations(id, aloft::quat_wxyz(1.0, 1.0, 0.0, 0.0), 1e-3, out) ==
              Status::non_unit_quaternion);
  ALOFT_CHECK(aloft::omega_world_from_orientations(aloft::quat_wxyz(std::nan(""), 0.0, 0.0, 0.0), id, 1e-3,
                                                   out) == Status::non_finite_input);
  ALOFT_CHECK(out == Vec3<double>(7.0, 7.0, 7.0));
}
