// The integrators refuse NaN states, non-unit quaternions and non-positive steps, and
// leave the state untouched when they do.
#include <limits>

#include "aloft/dynamics/rk4_integrator.hpp"
#include "aloft/dynamics/splitting_integrator.hpp"
#include "test_api.hpp"

namespace {

using aloft::Status;
using aloft::Vec3;

template <typename S, typename Integrator>
void check_refusals() {
  aloft::InertiaTensor<S> inertia;
  ALOFT_REQUIRE(aloft::InertiaTensor<S>::make_box(S(1), S(0.1), S(0.2), S(0.3), inertia) == Status::ok);
  const Integrator integrator(inertia);
  aloft::RigidBodyState<S> state;
  state.omega_body = Vec3<S>(S(1), S(2), S(3));
  const aloft::RigidBodyState<S> before = state;
  const S nan = std::numeric_limits<S>::quiet_NaN();
  const S inf = std::numeric_limits<S>::infinity();
  ALOFT_CHECK(integrator.step(state, S(0)) == Status::non_positive_time_step);
  ALOFT_CHECK(integrator.step(state, S(-1e-3)) == Status::non_positive_time_step);
  ALOFT_CHECK(integrator.step(state, nan) == Status::non_finite_input);
  ALOFT_CHECK(integrator.step(state, inf) == Status::non_finite_input);
  ALOFT_CHECK(state.orientation.coeffs() == before.orientation.coeffs());
  ALOFT_CHECK(state.omega_body == before.omega_body);

  aloft::RigidBodyState<S> bad_rate = state;
  bad_rate.omega_body.y() = nan;
  ALOFT_CHECK(integrator.step(bad_rate, S(1e-3)) == Status::non_finite_input);
  ALOFT_CHECK(std::isnan(bad_rate.omega_body.y()));
  ALOFT_CHECK(bad_rate.orientation.coeffs() == before.orientation.coeffs());

  aloft::RigidBodyState<S> bad_q = state;
  bad_q.orientation = aloft::quat_wxyz(S(1), S(0.5), S(0), S(0));
  const auto bad_coeffs = bad_q.orientation.coeffs();
  ALOFT_CHECK(integrator.step(bad_q, S(1e-3)) == Status::non_unit_quaternion);
  ALOFT_CHECK(bad_q.orientation.coeffs() == bad_coeffs);
  ALOFT_CHECK(bad_q.omega_body == before.omega_body);

  ALOFT_CHECK(integrator.step(state, S(1e-3)) == Status::ok);
  ALOFT_CHECK(integrator.step(state, S(1e-3), aloft::TimeDirection::backward) == Status::ok);
}

}  // namespace

ALOFT_TEST_CASE("integrators refuse bad steps and states untouched", "[dynamics][bad-input]") {
  check_refusals<double, aloft::Rk4Integrator<double>>();
  check_refusals<float, aloft::Rk4Integrator<float>>();
  check_refusals<double, aloft::SplittingIntegrator<double>>();
  check_refusals<float, aloft::SplittingIntegrator<float>>();
}
