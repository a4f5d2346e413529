#include <catch2/catch.hpp>

#include <cmath>

#include "study/inertia_perturbation.hpp"
#include "study/synthetic_throw.hpp"

using namespace aloft::host;

namespace {
// Angle by which the draw's principal axes are rotated from the nominal's. The GF
// cylinder's nominal axes are the body axes; for a draw with unchanged moments the
// stored axes are the rotated ones (make_from_principal keeps them when sorting).
double axes_rotation_deg(const aloft::InertiaTensor<double>& drawn) {
  const Eigen::Matrix3d r = drawn.principal_axes().toRotationMatrix();
  // Principal axis i may come back with either sign; the rotation angle of the frame is
  // recovered from the closest signed permutation (here the identity up to signs).
  double worst = 0.0;
  for (int i = 0; i < 3; ++i) worst = std::max(worst, std::acos(std::min(1.0, std::abs(r(i, i)))));
  return worst * 180.0 / M_PI;
}
}  // namespace

TEST_CASE("moment draws are uniform within the bound, each moment on its own") {
  const aloft::InertiaTensor<double> gf = paper_cylinder_body().inertia;
  const Eigen::Vector3d nominal = gf.principal_moments();
  double lowest = 1.0, highest = -1.0;
  int below_half = 0;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    SimulationRandom random(7, 0, static_cast<std::uint64_t>(i));
    const auto drawn = draw_perturbed_inertia(gf, {PerturbationFamily::moments, 10.0}, random);
    // The tensor stays diagonal: the axes are untouched.
    CHECK(std::abs(drawn.tensor()(0, 1)) + std::abs(drawn.tensor()(0, 2)) + std::abs(drawn.tensor()(1, 2)) <
          1e-15);
    const double change_z = drawn.tensor()(2, 2) / nominal(2) - 1.0;
    CHECK(std::abs(change_z) <= 0.1 + 1e-12);
    lowest = std::min(lowest, change_z);
    highest = std::max(highest, change_z);
    if (std::abs(change_z) < 0.05) ++below_half;
  }
  CHECK(lowest < -0.098);
  CHECK(highest > 0.098);
  CHECK(below_half == Approx(n / 2).margin(n * 0.04));  // uniform: half within half the bound
}

TEST_CASE("axes draws rotate the principal axes by at most the bound, uniformly in the ball") {
  const aloft::InertiaTensor<double> gf = paper_cylinder_body().inertia;
  int within_half = 0;
  double largest = 0.0;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    SimulationRandom random(11, 0, static_cast<std::uint64_t>(i));
    const auto drawn = draw_perturbed_inertia(gf, {PerturbationFamily::axes, 10.0}, random);
    CHECK((drawn.principal_moments() - gf.principal_moments()).norm() < 1e-15);
    // Rotation angle between nominal (identity) and drawn axes.
    const double angle =
        aloft::angle_between(Eigen::Quaterniond::Identity(), drawn.principal_axes()) * 180.0 / M_PI;
    CHECK(angle <= 10.0 + 1e-9);
    CHECK(axes_rotation_deg(drawn) <= 10.0 + 1e-9);  // no axis leaves its cone
    largest = std::max(largest, angle);
    if (angle <= 5.0) ++within_half;
  }
  CHECK(largest > 9.5);
  // Uniform in the ball's volume: an eighth lies within half the radius.
  CHECK(within_half == Approx(n / 8).margin(n * 0.02));
}

TEST_CASE("draws of every analysis are paired: the same unit perturbation scaled by the bound") {
  const aloft::InertiaTensor<double> gf = paper_cylinder_body().inertia;
  for (std::uint64_t i = 0; i < 50; ++i) {
    SimulationRandom a(3, 0, i), b(3, 0, i), c(3, 0, i);
    const auto m5 = draw_perturbed_inertia(gf, {PerturbationFamily::moments, 5.0}, a);
    const auto m10 = draw_perturbed_inertia(gf, {PerturbationFamily::moments, 10.0}, b);
    const auto both10 = draw_perturbed_inertia(gf, {PerturbationFamily::both, 10.0}, c);
    const Eigen::Vector3d n = gf.tensor().diagonal();
    const Eigen::Vector3d d5 = m5.tensor().diagonal().cwiseQuotient(n) - Eigen::Vector3d::Ones();
    const Eigen::Vector3d d10 = m10.tensor().diagonal().cwiseQuotient(n) - Eigen::Vector3d::Ones();
    CHECK((2.0 * d5 - d10).norm() < 1e-12);
    // "both" has the moments of "moments" (as a set) with rotated axes.
    CHECK((both10.principal_moments() - m10.principal_moments()).norm() < 1e-15);
  }
}

TEST_CASE("the ball is only part of the rotations that keep every axis within the bound") {
  // 12.26° about (1,1,1)/√3 moves each body axis by 10.0°: within a 10° cone for every
  // axis, yet outside the 10° ball of rotation vectors.
  const double angle = 12.26 * M_PI / 180.0;
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(angle, Eigen::Vector3d(1.0, 1.0, 1.0).normalized()).toRotationMatrix();
  for (int i = 0; i < 3; ++i) {
    const double moved = std::acos(r(i, i)) * 180.0 / M_PI;
    INFO("axis " << i << " moved by " << moved << " deg");
    CHECK(moved == Approx(10.0).margin(0.01));
  }
  CHECK(angle * 180.0 / M_PI > 10.0);
}

TEST_CASE("cardan axes draws: three independent angles, each uniform within the bound") {
  const aloft::InertiaTensor<double> gf = paper_cylinder_body().inertia;
  double largest = 0.0;
  int beyond_ball = 0;
  int within_half[3] = {0, 0, 0};
  const int n = 4000;
  const double to_deg = 180.0 / M_PI;
  for (int i = 0; i < n; ++i) {
    SimulationRandom random(13, 0, static_cast<std::uint64_t>(i));
    const auto drawn =
        draw_perturbed_inertia(gf, {PerturbationFamily::axes, 10.0, AxesSampler::cardan}, random);
    CHECK((drawn.principal_moments() - gf.principal_moments()).norm() < 1e-15);
    // Back to the three angles of R = Rx(a) Ry(b) Rz(c).
    const Eigen::Matrix3d r = drawn.principal_axes().toRotationMatrix();
    const double angles[3] = {std::atan2(-r(1, 2), r(2, 2)) * to_deg, std::asin(r(0, 2)) * to_deg,
                              std::atan2(-r(0, 1), r(0, 0)) * to_deg};
    for (int k = 0; k < 3; ++k) {
      CHECK(std::abs(angles[k]) <= 10.0 + 1e-9);
      if (std::abs(angles[k]) <= 5.0) ++within_half[k];
    }
    const double angle =
        aloft::angle_between(Eigen::Quaterniond::Identity(), drawn.principal_axes()) * to_deg;
    largest = std::max(largest, angle);
    if (angle > 10.0) ++beyond_ball;
  }
  for (int k = 0; k < 3; ++k) CHECK(within_half[k] == Approx(n / 2).margin(n * 0.04));
  // Three angles of up to 10° reach rotations the ball does not (up to 17.3°).
  CHECK(largest > 14.0);
  CHECK(largest <= 17.4);
  CHECK(beyond_ball > n / 10);
}
