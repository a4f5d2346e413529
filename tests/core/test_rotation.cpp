// Quaternion exp/log and angle measures, near 0, mid-range and near pi (Sophus style).
#include "aloft/dynamics/rotation.hpp"
#include "test_api.hpp"
#include "tolerances.hpp"

namespace {

template <typename S>
void check_exp_log_round_trip() {
  using aloft::Vec3;
  const S tol = aloft_test::Tolerances<S>::rounding;
  const Vec3<S> axis = Vec3<S>(S(1), S(-2), S(0.5)).normalized();
  const S angles[] = {S(0), S(1e-11), S(1e-6), S(1e-3), S(0.5), S(2), S(3.1)};
  for (S angle : angles) {
    const Vec3<S> r = axis * angle;
    const aloft::Quat<S> q = aloft::quat_exp(r);
    ALOFT_CHECK(std::abs(q.norm() - S(1)) < tol);
    const Vec3<S> back = aloft::quat_log(q);
    ALOFT_CHECK((back - r).norm() <= tol * (S(1) + angle));
  }
}

template <typename S>
void check_angle_between() {
  const S tol = aloft_test::Tolerances<S>::rounding;
  const aloft::Quat<S> a = aloft::quat_exp(aloft::Vec3<S>(S(0.3), S(-0.2), S(1.0)));
  const S angles[] = {S(1e-9), S(1e-4), S(0.7), S(3.0)};
  for (S angle : angles) {
    const aloft::Quat<S> b = a * aloft::quat_exp(aloft::Vec3<S>(S(0), angle, S(0)));
    ALOFT_CHECK(std::abs(aloft::angle_between(a, b) - angle) <= tol * (S(1) + angle));
    // -b is the same rotation.
    const aloft::Quat<S> minus_b(-b.w(), -b.x(), -b.y(), -b.z());
    ALOFT_CHECK(std::abs(aloft::angle_between(a, minus_b) - angle) <= tol * (S(1) + angle));
  }
}

}  // namespace

ALOFT_TEST_CASE("exp and log of rotations round-trip from 0 to near pi", "[rotation]") {
  check_exp_log_round_trip<double>();
  check_exp_log_round_trip<float>();
}

ALOFT_TEST_CASE("angle between orientations resolves tiny angles", "[rotation]") {
  check_angle_between<double>();
  check_angle_between<float>();
}

ALOFT_TEST_CASE("unit check rejects non-unit and non-finite quaternions", "[rotation]") {
  ALOFT_CHECK(aloft::is_unit(aloft::Quat<double>::Identity()));
  ALOFT_CHECK(!aloft::is_unit(aloft::quat_wxyz(1.1, 0.0, 0.0, 0.0)));
  ALOFT_CHECK(!aloft::is_unit(aloft::quat_wxyz(std::nan(""), 0.0, 0.0, 0.0)));
  ALOFT_CHECK(!aloft::is_unit(aloft::quat_wxyz(0.5f, 0.5f, 0.5f, 0.4f)));
}

ALOFT_TEST_CASE("quaternions are built w, x, y, z", "[rotation]") {
  const aloft::Quat<double> q = aloft::quat_wxyz(0.5, 0.1, 0.2, 0.3);
  ALOFT_CHECK(q.w() > 0.49);
  ALOFT_CHECK(q.w() < 0.51);
  ALOFT_CHECK(q.z() > 0.29);
  ALOFT_CHECK(q.z() < 0.31);
}
