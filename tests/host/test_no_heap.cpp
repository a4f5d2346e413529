// Proof that lib/ never touches the heap: every public path of the core, in float and
// double, runs between two readings of a counter of all heap allocations, with Eigen's
// own run-time malloc check armed as well (EIGEN_RUNTIME_NO_MALLOC, asserts on).
#include <catch2/catch.hpp>

#include <limits>

#include "aloft/aloft.hpp"
#include "heap_counter.hpp"

namespace {

// The onboard pipeline over a held / spinning free flight / impact sequence with a gap
// and a clipped sample, with r known or fitted. Returns a value so nothing is optimised out.
template <typename S>
S exercise_pipeline(const aloft::InertiaTensor<S>& inertia, bool r_known) {
  using aloft::Vec3;
  aloft::OnboardPipelineSettings<S> settings;
  settings.imu_position_known = r_known;
  settings.imu_position_m = Vec3<S>(S(0.03), S(0), S(0));
  aloft::OnboardPipeline<S, 8> pipeline(inertia, settings);
  const Vec3<S> spin = inertia.principal_axes() * Vec3<S>(S(0), S(0), S(20));
  S sink = S(0);
  for (int k = 0; k < 2000; ++k) {
    aloft::ImuSample<S> sample;
    sample.t_us = 1000000u + static_cast<std::uint64_t>(k) * 1000u + (k > 1500 ? 50000u : 0u);
    const bool flying = k >= 500 && k < 1200;
    sample.gyro_rad_s = flying ? spin : Vec3<S>::Zero();
    sample.accel_m_s2 = flying ? Vec3<S>(spin.cross(spin.cross(settings.imu_position_m)))
                               : Vec3<S>(S(0), S(0), k == 1200 ? S(300) : S(9.81));
    if (k == 1501) sample.flags = aloft::imu_gap_before;
    if (k == 900) sample.flags = aloft::imu_gyro_clipped;
    REQUIRE(pipeline.push(sample) == aloft::Status::ok);
    aloft::FlightResult<S> flight;
    while (pipeline.take_finished_flight(flight))
      sink += flight.overall.rms_da() + flight.imu_position_m.norm();
  }
  pipeline.finish();
  return sink + static_cast<S>(pipeline.stream().gaps);
}

// Everything lib/ offers, once, for scalar S. Returns a value so nothing is optimised out.
template <typename S>
S exercise_core() {
  using aloft::Status;
  using aloft::Vec3;
  S sink = S(0);
  aloft::InertiaTensor<S> cylinder;
  aloft::InertiaTensor<S> box;
  aloft::InertiaTensor<S> sphere;
  aloft::InertiaTensor<S> full;
  aloft::InertiaTensor<S> principal;
  REQUIRE(aloft::InertiaTensor<S>::make_cylinder(S(10), S(0.065), S(0.097), cylinder) == Status::ok);
  REQUIRE(aloft::InertiaTensor<S>::make_box(S(1), S(0.1), S(0.2), S(0.3), box) == Status::ok);
  REQUIRE(aloft::InertiaTensor<S>::make_sphere(S(1), S(0.1), sphere) == Status::ok);
  REQUIRE(aloft::InertiaTensor<S>::make_from_tensor(box.tensor(), full) == Status::ok);
  REQUIRE(aloft::InertiaTensor<S>::make_from_principal(Vec3<S>(S(1), S(2), S(2.5)),
                                                       aloft::quat_wxyz(S(0.8), S(0.6), S(0), S(0)),
                                                       principal) == Status::ok);

  aloft::RigidBodyState<S> a;
  a.omega_body = Vec3<S>(S(1), S(10), S(0.5));
  aloft::RigidBodyState<S> b = a;
  const aloft::Rk4Integrator<S> rk4(principal);
  const aloft::SplittingIntegrator<S> splitting(principal);
  aloft::DeviationStats<S> stats;
  for (int k = 0; k < 100; ++k) {
    const aloft::Quat<S> before = a.orientation;
    REQUIRE(rk4.step(a, S(1e-3)) == Status::ok);
    REQUIRE(splitting.step(b, S(1e-3), aloft::TimeDirection::backward) == Status::ok);
    Vec3<S> body = Vec3<S>::Zero();
    Vec3<S> world = Vec3<S>::Zero();
    REQUIRE(aloft::omega_body_from_orientations(before, a.orientation, S(1e-3), body) == Status::ok);
    REQUIRE(aloft::omega_world_from_orientations(before, a.orientation, S(1e-3), world) == Status::ok);
    REQUIRE(stats.add(body, a.omega_body) == Status::ok);
    sink += world.norm() + aloft::angle_between(a.orientation, b.orientation);
  }
  sink += stats.rms_da() + stats.rms_relative_error();

  aloft::OnboardCheckSettings<S> settings;
  settings.seed_every = 7;
  aloft::OnboardCheck<S, 8> check(principal, settings);
  aloft::RigidBodyState<S> truth = a;
  for (int k = 0; k < 200; ++k) {
    REQUIRE(rk4.step(truth, S(1e-3)) == Status::ok);
    REQUIRE(check.update(truth.omega_body, S(1e-3)) == Status::ok);
    REQUIRE(check.update(Vec3<S>(S(1), std::numeric_limits<S>::quiet_NaN(), S(0)), S(1e-3)) ==
            Status::non_finite_input);  // a refused sample
  }
  return sink + check.overall().rms_da() + check.seed(0).stats.rms_da() + exercise_pipeline(principal, true) +
         exercise_pipeline(principal, false);
}

}  // namespace

TEST_CASE("the heap counter sees an allocation (so the next test can fail)", "[no-heap]") {
  const std::size_t before = aloft_test::heap_allocations();
  int* volatile p = new int(3);
  delete p;
  void* volatile q = std::malloc(16);
  std::free(q);
  CHECK(aloft_test::heap_allocations() - before == 2);
}

TEST_CASE("no path of lib/ allocates, in float or double", "[no-heap]") {
  Eigen::internal::set_is_malloc_allowed(false);
  const std::size_t before = aloft_test::heap_allocations();
  const double d = exercise_core<double>();
  const float f = exercise_core<float>();
  const std::size_t after = aloft_test::heap_allocations();
  Eigen::internal::set_is_malloc_allowed(true);
  CHECK(after - before == 0);
  CHECK(std::isfinite(d));
  CHECK(std::isfinite(f));
}
