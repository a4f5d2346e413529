// Deviation angle, relative error and their fixed-memory statistics.
#include <algorithm>

#include "aloft/dynamics/deviation.hpp"
#include "test_api.hpp"

namespace {

using aloft::Status;
using aloft::Vec3;

template <typename S>
void check_known_angles() {
  const Vec3<S> x(S(2), S(0), S(0));
  const S pi = S(3.14159265358979323846);
  ALOFT_CHECK(std::abs(aloft::deviation_angle(x, Vec3<S>(S(0), S(5), S(0))) - pi / S(2)) < S(1e-6));
  ALOFT_CHECK(std::abs(aloft::deviation_angle(x, Vec3<S>(S(-1), S(0), S(0))) - pi) < S(1e-6));
  ALOFT_CHECK(std::abs(aloft::deviation_angle(x, Vec3<S>(S(1), S(1), S(0))) - pi / S(4)) < S(1e-6));
  // Tiny angles are resolved (atan2, not acos of a dot product).
  const S tiny = S(1e-6);
  ALOFT_CHECK(std::abs(aloft::deviation_angle(x, Vec3<S>(S(1), tiny, S(0))) - tiny) < tiny * S(1e-3));
  ALOFT_CHECK(std::abs(aloft::relative_error(Vec3<S>(S(3), S(4), S(0)), Vec3<S>(S(0), S(4), S(0))) -
                       S(0.75)) < S(1e-6));
}

}  // namespace

ALOFT_TEST_CASE("deviation angle and relative error of known vectors", "[deviation]") {
  check_known_angles<double>();
  check_known_angles<float>();
}

ALOFT_TEST_CASE("running statistics match a direct computation", "[deviation]") {
  aloft::DeviationStats<double> stats;
  aloft::DeviationStats<double> first_half;
  aloft::DeviationStats<double> second_half;
  double sum_sq_da = 0.0;
  double sum_sq_rel = 0.0;
  double max_da = 0.0;
  const Vec3<double> measured(1.0, 2.0, 3.0);
  for (int i = 0; i < 100; ++i) {
    const Vec3<double> simulated = measured + Vec3<double>(0.01 * i, -0.02 * (i % 7), 0.003 * i);
    const double da = aloft::deviation_angle(simulated, measured);
    const double rel = aloft::relative_error(simulated, measured);
    sum_sq_da += da * da;
    sum_sq_rel += rel * rel;
    max_da = std::max(max_da, da);
    ALOFT_REQUIRE(stats.add(simulated, measured) == Status::ok);
    ALOFT_REQUIRE((i < 40 ? first_half : second_half).add(simulated, measured) == Status::ok);
  }
  ALOFT_CHECK(stats.count() == 100u);
  ALOFT_CHECK(std::abs(stats.rms_da() - std::sqrt(sum_sq_da / 100.0)) < 1e-14);
  ALOFT_CHECK(std::abs(stats.rms_relative_error() - std::sqrt(sum_sq_rel / 100.0)) < 1e-14);
  ALOFT_CHECK(std::abs(stats.max_da() - max_da) < 1e-15);
  first_half.merge(second_half);
  ALOFT_CHECK(first_half.count() == 100u);
  ALOFT_CHECK(std::abs(first_half.rms_da() - stats.rms_da()) < 1e-14);
}

ALOFT_TEST_CASE("a long float run keeps its mean square", "[deviation]") {
  // 10^6 equal samples: a plain float running sum would stall near 2^24 ulp; the
  // incremental mean does not.
  aloft::DeviationStats<float> stats;
  for (int i = 0; i < 1000000; ++i) stats.add_values(0.01f, 0.02f);
  ALOFT_CHECK(std::abs(stats.rms_da() - 0.01f) < 1e-5f);
  ALOFT_CHECK(std::abs(stats.rms_relative_error() - 0.02f) < 1e-5f);
}

ALOFT_TEST_CASE("statistics refuse non-finite and zero measurements untouched", "[deviation][bad-input]") {
  aloft::DeviationStats<float> stats;
  ALOFT_REQUIRE(stats.add(Vec3<float>(1, 0, 0), Vec3<float>(0, 1, 0)) == Status::ok);
  const float rms = stats.rms_da();
  ALOFT_CHECK(stats.add(Vec3<float>(std::nanf(""), 0, 0), Vec3<float>(0, 1, 0)) == Status::non_finite_input);
  ALOFT_CHECK(stats.add(Vec3<float>(1, 0, 0), Vec3<float>(0, 0, 0)) == Status::zero_vector);
  ALOFT_CHECK(stats.count() == 1u);
  ALOFT_CHECK(std::abs(stats.rms_da() - rms) <= 0.0f);
}
