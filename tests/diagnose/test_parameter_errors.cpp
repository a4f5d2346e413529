// diagnose/parameter_errors: the arrow (Schur complement) path gives the full
// eigen-decomposition's covariance and standard errors, and hands over to it whenever
// the data leave a direction uninformed or a flight's rate block singular.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "diagnose/3_fit/parameter_errors.hpp"

using namespace aloft::host::diagnose;

namespace {

constexpr int kShared = 4, kLocal = 3, kFlights = 6, kRowsPerFlight = 30;

// J^T J of a pooled fit's Jacobian: every flight's rows see the shared columns and its
// own three rate columns only. `shape` edits each flight's block of rows.
template <typename Shape>
Eigen::MatrixXd arrow_normal(Shape shape) {
  std::mt19937 rng(11);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const int size = kShared + kLocal * kFlights;
  Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(kRowsPerFlight * kFlights, size);
  for (int f = 0; f < kFlights; ++f) {
    Eigen::MatrixXd rows(kRowsPerFlight, kShared + kLocal);
    for (Eigen::Index i = 0; i < rows.size(); ++i) rows.data()[i] = gauss(rng);
    shape(f, rows);
    jacobian.block(kRowsPerFlight * f, 0, kRowsPerFlight, kShared) = rows.leftCols(kShared);
    jacobian.block(kRowsPerFlight * f, kShared + kLocal * f, kRowsPerFlight, kLocal) = rows.rightCols(kLocal);
  }
  return jacobian.transpose() * jacobian;
}

void require_same(const ParameterErrors& a, const ParameterErrors& b) {
  for (int i = 0; i < kShared; ++i) {
    INFO("parameter " << i << ": " << a.standard_error(i) << " vs " << b.standard_error(i));
    REQUIRE(std::isinf(a.standard_error(i)) == std::isinf(b.standard_error(i)));
    if (!std::isinf(b.standard_error(i))) {
      REQUIRE(a.standard_error(i) == Approx(b.standard_error(i)).epsilon(1e-9));
    }
  }
  const double scale = b.covariance.cwiseAbs().maxCoeff();
  REQUIRE((a.covariance - b.covariance).cwiseAbs().maxCoeff() <= 1e-9 * scale);
}

}  // namespace

TEST_CASE("parameter_errors through the Schur complement equals the full decomposition",
          "[parameter_errors]") {
  const Eigen::MatrixXd normal = arrow_normal([](int, Eigen::MatrixXd&) {});
  const ParameterErrors arrow = parameter_errors(normal, kShared, kLocal, 2.5);
  REQUIRE(arrow.through_schur);
  require_same(arrow, parameter_errors_full(normal, kShared, 2.5));
}

TEST_CASE("parameter_errors hands an uninformed direction to the full decomposition", "[parameter_errors]") {
  SECTION("a shared parameter the data never see") {
    const Eigen::MatrixXd normal = arrow_normal([](int, Eigen::MatrixXd& rows) { rows.col(2).setZero(); });
    const ParameterErrors arrow = parameter_errors(normal, kShared, kLocal, 1.0);
    REQUIRE_FALSE(arrow.through_schur);
    REQUIRE(std::isinf(arrow.standard_error(2)));
    REQUIRE(std::isfinite(arrow.standard_error(0)));
    require_same(arrow, parameter_errors_full(normal, kShared, 1.0));
  }
  SECTION("a shared parameter indistinguishable from every flight's first rate") {
    const Eigen::MatrixXd normal =
        arrow_normal([](int, Eigen::MatrixXd& rows) { rows.col(1) = rows.col(kShared); });
    const ParameterErrors arrow = parameter_errors(normal, kShared, kLocal, 1.0);
    REQUIRE_FALSE(arrow.through_schur);
    REQUIRE(std::isinf(arrow.standard_error(1)));
    require_same(arrow, parameter_errors_full(normal, kShared, 1.0));
  }
  SECTION("a direction informed a trillionth as well as the rest") {
    const Eigen::MatrixXd normal = arrow_normal([](int, Eigen::MatrixXd& rows) { rows.col(3) *= 1e-7; });
    const ParameterErrors arrow = parameter_errors(normal, kShared, kLocal, 1.0);
    REQUIRE_FALSE(arrow.through_schur);
    require_same(arrow, parameter_errors_full(normal, kShared, 1.0));
  }
  SECTION("a flight whose rates the data do not inform (a singular rate block)") {
    const Eigen::MatrixXd normal = arrow_normal([](int flight, Eigen::MatrixXd& rows) {
      if (flight == 3) rows.col(kShared + 2).setZero();
    });
    const ParameterErrors arrow = parameter_errors(normal, kShared, kLocal, 1.0);
    REQUIRE_FALSE(arrow.through_schur);
    require_same(arrow, parameter_errors_full(normal, kShared, 1.0));
  }
}

TEST_CASE("parameter_errors takes the arrow path when moderately conditioned", "[parameter_errors]") {
  // Condition ~1e6: far from the 1e-12 cutoff, so both paths keep every direction.
  const Eigen::MatrixXd normal = arrow_normal([](int, Eigen::MatrixXd& rows) { rows.col(0) *= 1e-3; });
  const ParameterErrors arrow = parameter_errors(normal, kShared, kLocal, 0.3);
  REQUIRE(arrow.through_schur);
  require_same(arrow, parameter_errors_full(normal, kShared, 0.3));
}
