#include <catch2/catch.hpp>

#include <cmath>

#include "aloft/dynamics/rk4_integrator.hpp"
#include "study/synthetic_throw.hpp"
#include "study/tangent_spline_resampler.hpp"

using namespace aloft::host;

TEST_CASE("the resampler reproduces a constant body rate exactly, on uneven knots") {
  const Eigen::Vector3d w(1.0, -2.0, 3.0);
  const Eigen::Quaterniond q0 = Eigen::Quaterniond(0.8, 0.1, 0.5, -0.3).normalized();
  std::vector<double> t = {0.0, 0.004, 0.009, 0.012, 0.020, 0.024};
  std::vector<Eigen::Quaterniond> q;
  for (double ti : t) q.push_back(q0 * aloft::quat_exp(Eigen::Vector3d(w * ti)));
  const ResampledPoses r = resample_poses(t, q, 1000.0);
  REQUIRE(r.time_s.size() == 25);
  for (std::size_t i = 0; i < r.time_s.size(); ++i) {
    const Eigen::Quaterniond exact = q0 * aloft::quat_exp(Eigen::Vector3d(w * r.time_s[i]));
    CHECK(aloft::angle_between(exact, r.orientation[i]) < 1e-12);
    CHECK((r.omega_body[i] - w).norm() < 1e-9);
  }
}

TEST_CASE("the right Jacobian and its inverse are inverses, also near zero") {
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(0.3, -1.2, 0.7), Eigen::Vector3d(1e-5, 2e-5, 0.0), Eigen::Vector3d(2.5, 0.1, 0.0)}) {
    const Eigen::Matrix3d product = so3_right_jacobian(p) * so3_right_jacobian_inverse(p);
    CHECK((product - Eigen::Matrix3d::Identity()).norm() < 1e-12);
  }
  // exp(p + d) ≈ exp(p) exp(J_r(p) d) to first order.
  const Eigen::Vector3d p(0.4, -0.9, 0.2), d(1e-7, -2e-7, 3e-7);
  const Eigen::Quaterniond lhs = aloft::quat_exp(Eigen::Vector3d(p + d));
  const Eigen::Quaterniond rhs =
      aloft::quat_exp(p) * aloft::quat_exp(Eigen::Vector3d(so3_right_jacobian(p) * d));
  CHECK(aloft::angle_between(lhs, rhs) < 1e-12);
}

TEST_CASE("250 Hz poses of the torque-free throw resampled to 1 kHz follow the true motion") {
  SyntheticThrowSettings settings;
  settings.marker_noise_m = 0.0;
  const SyntheticThrow truth = make_synthetic_throw(settings);
  const ResampledPoses r = resample_poses(truth.true_poses.time_s, truth.true_poses.orientation, 1000.0);
  REQUIRE(r.time_s.size() == 873);
  CHECK(r.time_s.back() == Approx(0.872));
  // The truth at 1 kHz, integrated finely.
  const aloft::Rk4Integrator<double> integrator(truth.body.inertia);
  aloft::RigidBodyState<double> s{settings.initial_orientation.normalized(),
                                  settings.initial_omega_body_rad_s()};
  double worst_angle = 0.0, worst_rate = 0.0;
  for (std::size_t i = 0; i < r.time_s.size(); ++i) {
    if (i > 0) {
      for (int k = 0; k < 10; ++k) {
        REQUIRE(integrator.step(s, 1e-4, aloft::TimeDirection::forward) == aloft::Status::ok);
      }
    }
    worst_angle = std::max(worst_angle, aloft::angle_between(s.orientation, r.orientation[i]));
    worst_rate = std::max(worst_rate, (s.omega_body - r.omega_body[i]).norm());
  }
  INFO("worst orientation error " << worst_angle << " rad, worst rate error " << worst_rate);
  CHECK(worst_angle < 2e-7);
  CHECK(worst_rate < 2e-4);  // rad/s, of 9.4 rad/s
}

TEST_CASE("the resampler refuses too few poses and times that do not increase") {
  const Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  CHECK_THROWS(resample_poses({0.0, 0.1}, {q, q}, 1000.0));
  CHECK_THROWS(resample_poses({0.0, 0.1, 0.1}, {q, q, q}, 1000.0));
}
