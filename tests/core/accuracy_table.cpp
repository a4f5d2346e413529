// The "Accuracy" table of docs/accuracy-and-speed.md, measured: a hidden test case (tag [.accuracy_table])
// that prints the table's rows, the measured worst case of each check beside the issue's bound and the bound
// the tests hold it to (tolerances.hpp). Catch2 builds only.
//   build/host/tests/core/aloft_core_tests "[.accuracy_table]" -o /dev/null
#include <cstdio>
#include <cstdlib>
#include <string>

#include "accuracy_measures.hpp"
#include "tolerances.hpp"

namespace {

using aloft_test::Accuracy;
using Order = aloft::SplittingIntegrator<double>::Order;

// 1.5e-9 as the table writes it (printf would give 1.5e-09).
std::string sci(double value, int decimals) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*e", decimals, value);
  std::string s(text);
  const std::size_t e = s.find('e');
  const int exponent = std::atoi(s.c_str() + e + 1);
  return s.substr(0, e) + "e" + std::to_string(exponent);
}

void row(const std::string& check, const char* issue_bound, const std::string& measured, double test_bound) {
  std::printf("| %s | %s | %s | %s |\n", check.c_str(), issue_bound, measured.c_str(),
              sci(test_bound, 0).c_str());
}

std::string rad(double value) { return sci(value, 1) + " rad"; }

template <typename S>
double worst_symmetric_top() {
  double worst = 0.0;
  for (const auto& top : aloft_test::kCylinderTops) {
    worst = std::max(worst, aloft_test::symmetric_top_orientation_error<S, aloft::Rk4Integrator<S>>(top));
  }
  return worst;
}

template <typename S>
double worst_asymmetric_top() {
  const aloft_test::AsymmetricTop top = aloft_test::flipping_top();
  double worst = 0.0;
  for (const auto& frame :
       {aloft::Quat<double>::Identity(), aloft::quat_wxyz(0.8, 0.2, -0.5, 0.26).normalized()}) {
    worst = std::max(worst, aloft_test::asymmetric_top_direction_error<S>(top, frame, false));
  }
  return worst;
}

}  // namespace

TEST_CASE("the docs' accuracy table, measured", "[.accuracy_table]") {
  const aloft::InertiaTensor<double> inertia = aloft_test::tumbling_body();
  const aloft::RigidBodyState<double> start = aloft_test::tumbling_start(inertia);
  const aloft_test::Drift rk4 = aloft_test::invariant_drift(aloft::Rk4Integrator<double>(inertia), start);
  const aloft_test::Drift split =
      aloft_test::invariant_drift(aloft::SplittingIntegrator<double>(inertia, Order::fourth), start);
  double rate_error = 0.0;
  const double rk4_trip =
      aloft_test::round_trip_error(aloft::Rk4Integrator<double>(inertia), start, &rate_error);
  const double split_trip =
      aloft_test::round_trip_error(aloft::SplittingIntegrator<double>(inertia), start, &rate_error);

  std::printf("| check | issue's bound | measured | test bound |\n| --- | --- | --- | --- |\n");
  row("RK4 vs closed-form symmetric top, orientation, double", "1e-8 rad", rad(worst_symmetric_top<double>()),
      Accuracy<double>::symmetric_top_orientation);
  row("RK4 vs symmetric top, float", "1e-4 rad", rad(worst_symmetric_top<float>()),
      Accuracy<float>::symmetric_top_orientation);
  row("RK4 vs Jacobi-elliptic asymmetric top (through an intermediate-axis flip, full "
      "tensor), ω direction, double",
      "1e-8 rad", rad(worst_asymmetric_top<double>()), Accuracy<double>::asymmetric_top_direction);
  row("same, float", "1e-3 rad", rad(worst_asymmetric_top<float>()),
      Accuracy<float>::asymmetric_top_direction);
  row("RK4 energy drift / ‖L‖ drift (relative, double)", "1e-9",
      sci(rk4.energy, 1) + " / " + sci(rk4.momentum, 1), Accuracy<double>::rk4_invariant_drift);
  row("splitting (4th-order Yoshida composition), ‖L‖ drift", "1e-13", sci(split.momentum, 1),
      Accuracy<double>::splitting_momentum_drift);
  row("forward then backward, RK4, double", "1e-9 rad", rad(rk4_trip), Accuracy<double>::rk4_round_trip);
  row("forward then backward, splitting (time-symmetric)", "round-off", rad(split_trip),
      Accuracy<double>::splitting_round_trip);
}
