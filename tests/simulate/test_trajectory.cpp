// simulate_trajectory, the code behind `aloft simulate`, against the exact symmetric top.
#include <catch2/catch.hpp>

#include <algorithm>

#include "exact_tops.hpp"
#include "simulate/trajectory.hpp"

using aloft::host::Precision;
using aloft::host::TrajectoryRequest;

namespace {

double worst_orientation_error(const TrajectoryRequest& request, const aloft_test::SymmetricTop& top) {
  aloft::InertiaTensor<double> inertia;
  REQUIRE(aloft::InertiaTensor<double>::make_from_principal(Eigen::Vector3d(top.it, top.it, top.i3),
                                                            Eigen::Quaterniond::Identity(),
                                                            inertia) == aloft::Status::ok);
  const auto samples = aloft::host::simulate_trajectory(inertia, request);
  REQUIRE(samples.size() == 1001);
  double worst = 0.0;
  for (const auto& s : samples) {
    worst = std::max(worst, aloft::angle_between(s.state.orientation, top.orientation(s.t_s)));
  }
  return worst;
}

}  // namespace

TEST_CASE("simulate_trajectory follows the symmetric top in double and float", "[simulate]") {
  const aloft_test::SymmetricTop top{0.0183892, 0.0210806, Eigen::Vector3d(3.0, -4.0, 12.0),
                                     aloft::quat_wxyz(0.9, 0.1, -0.3, 0.3).normalized()};
  TrajectoryRequest request;
  request.initial.orientation = top.q0;
  request.initial.omega_body = top.omega0;
  request.duration_s = 1.0;
  request.rate_hz = 1000.0;
  CHECK(worst_orientation_error(request, top) < 5e-9);
  request.integrator = aloft::host::IntegratorKind::splitting;
  CHECK(worst_orientation_error(request, top) < 5e-8);
  request.integrator = aloft::host::IntegratorKind::rk4;
  request.precision = Precision::single_precision;
  CHECK(worst_orientation_error(request, top) < 2e-5);
}

TEST_CASE("samples far apart are reached in sub-steps of at most 1 ms", "[simulate]") {
  const aloft_test::SymmetricTop top{0.5, 1.0, Eigen::Vector3d(10.0, 8.0, 7.0),
                                     Eigen::Quaterniond::Identity()};
  aloft::InertiaTensor<double> inertia;
  REQUIRE(aloft::InertiaTensor<double>::make_from_principal(
              Eigen::Vector3d(0.5, 0.5, 1.0), Eigen::Quaterniond::Identity(), inertia) == aloft::Status::ok);
  TrajectoryRequest request;
  request.initial.omega_body = top.omega0;
  request.duration_s = 1.0;
  request.rate_hz = 10.0;  // 100 ms between samples
  const auto samples = aloft::host::simulate_trajectory(inertia, request);
  REQUIRE(samples.size() == 11);
  CHECK(std::abs(samples.back().t_s - 1.0) < 1e-12);
  CHECK(aloft::angle_between(samples.back().state.orientation, top.orientation(1.0)) < 5e-9);
}
