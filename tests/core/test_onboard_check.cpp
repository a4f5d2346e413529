// The onboard check: seeding, the K-simulation window, and its verdict on a gyro stream
// from an exactly known motion (release and landing are the pipeline's,
// tests/core/test_onboard_pipeline.cpp).
#include "aloft/onboard/onboard_check.hpp"
#include "exact_tops.hpp"
#include "test_api.hpp"

namespace {

using aloft::Status;
using aloft::Vec3;

// Gyro samples of the flipping asymmetric top (principal axes = body axes), 1 kHz.
const aloft_test::AsymmetricTop kTop{0.01, 0.02, 0.03, 8.0, 5.0, 0.3};

template <typename S>
aloft::InertiaTensor<S> top_inertia(double scale_i1) {
  aloft::InertiaTensor<S> inertia;
  const Status s = aloft::InertiaTensor<S>::make_from_principal(
      Vec3<S>(S(kTop.i1 * scale_i1), S(kTop.i2), S(kTop.i3)), aloft::Quat<S>::Identity(), inertia);
  ALOFT_REQUIRE(s == Status::ok);
  return inertia;
}

template <typename S, int K>
void feed(aloft::OnboardCheck<S, K>& check, int samples) {
  for (int k = 0; k < samples; ++k) {
    ALOFT_REQUIRE(check.update(kTop.omega(k * 1e-3).cast<S>(), S(1e-3)) == Status::ok);
  }
}

template <typename S>
void check_right_and_wrong_tensor() {
  aloft::OnboardCheckSettings<S> settings;
  settings.seed_every = 25;
  aloft::OnboardCheck<S, 8> right(top_inertia<S>(1.0), settings);
  aloft::OnboardCheck<S, 8> wrong(top_inertia<S>(1.15), settings);
  feed(right, 1000);
  feed(wrong, 1000);
  ALOFT_CHECK(right.seeds_started() == 40u);
  ALOFT_CHECK(right.live_simulations() == 8);
  // The right tensor: only integration and rounding error (radians).
  ALOFT_CHECK(right.overall().rms_da() < S(1e-4));
  ALOFT_CHECK(right.overall().rms_relative_error() < S(1e-4));
  // 15 % off in one moment: plainly visible.
  ALOFT_CHECK(wrong.overall().rms_da() > S(0.01));
  ALOFT_CHECK(wrong.overall().rms_da() > S(100) * right.overall().rms_da());
  // The window holds the 8 newest seeds, newest first.
  ALOFT_CHECK(right.seed(0).seed_number == 39u);
  ALOFT_CHECK(right.seed(7).seed_number == 32u);
  ALOFT_CHECK(right.seed(0).seeded_at_sample == 975u);
  ALOFT_CHECK(right.seed(1).stats.count() == 49u);  // 24 samples before the newest + 25
  ALOFT_CHECK(right.seed(0).stats.count() == 24u);
}

}  // namespace

ALOFT_TEST_CASE("onboard check: exact tensor agrees, a wrong one is caught", "[onboard]") {
  check_right_and_wrong_tensor<double>();
  check_right_and_wrong_tensor<float>();
}

ALOFT_TEST_CASE("onboard check refuses bad samples and keeps its state", "[onboard][bad-input]") {
  aloft::OnboardCheckSettings<double> settings;
  settings.seed_every = 5;
  aloft::OnboardCheck<double, 8> check(top_inertia<double>(1.0), settings);
  feed(check, 20);
  const double rms = check.overall().rms_da();
  const std::uint32_t count = check.overall().count();
  const double nan = std::nan("");
  ALOFT_CHECK(check.update(Vec3<double>(nan, 1, 1), 1e-3) == Status::non_finite_input);
  ALOFT_CHECK(check.update(Vec3<double>(1, 1, 1), 0.0) == Status::non_positive_time_step);
  ALOFT_CHECK(check.update(Vec3<double>(1, 1, 1), -1e-3) == Status::non_positive_time_step);
  ALOFT_CHECK(check.update(Vec3<double>(1, 1, 1), nan) == Status::non_finite_input);
  // The same dt rule for a sample known finite and for a clipped one.
  ALOFT_CHECK(check.update_finite(Vec3<double>(1, 1, 1), 0.0) == Status::non_positive_time_step);
  ALOFT_CHECK(check.update_finite(Vec3<double>(1, 1, 1), -1e-3) == Status::non_positive_time_step);
  ALOFT_CHECK(check.skip(0.0) == Status::non_positive_time_step);
  ALOFT_CHECK(check.skip(nan) == Status::non_finite_input);
  ALOFT_CHECK(check.airborne_samples() == 20u);
  ALOFT_CHECK(check.overall().count() == count);
  ALOFT_CHECK(std::abs(check.overall().rms_da() - rms) <= 0.0);
}
