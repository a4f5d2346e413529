// The Jacobi eigen-decomposition behind InertiaTensor::make_from_tensor, and the one-sided
// one through the Cholesky factor behind the tensor estimate: exact to rounding for
// distinct, nearly equal and equal eigenvalues, in float and double.
#include <algorithm>

#include "aloft/dynamics/symmetric_eigen.hpp"
#include "test_api.hpp"

namespace {

using aloft::Mat3;
using aloft::Vec3;

enum class Method { two_sided, through_cholesky };

template <typename S>
void check_decomposition(const Vec3<S>& eigenvalues, const aloft::Quat<S>& frame, S tolerance,
                         Method method = Method::two_sided) {
  const Mat3<S> r = frame.normalized().toRotationMatrix();
  const Mat3<S> a = r * eigenvalues.asDiagonal() * r.transpose();
  Vec3<S> values = Vec3<S>::Zero();
  Mat3<S> vectors = Mat3<S>::Zero();
  if (method == Method::two_sided) {
    aloft::symmetric_eigen_decomposition(a, values, vectors);
  } else {
    ALOFT_REQUIRE(aloft::positive_definite_eigen_decomposition(a, values, vectors));
  }
  const S scale = eigenvalues.cwiseAbs().maxCoeff();
  ALOFT_CHECK(values(0) <= values(1));
  ALOFT_CHECK(values(1) <= values(2));
  // Same spectrum as given (sorted), A V = V D, V orthonormal and right-handed.
  Vec3<S> sorted = eigenvalues;
  std::sort(sorted.data(), sorted.data() + 3);
  ALOFT_CHECK((values - sorted).norm() <= tolerance * scale);
  ALOFT_CHECK((a * vectors - vectors * values.asDiagonal()).norm() <= tolerance * scale);
  ALOFT_CHECK((vectors.transpose() * vectors - Mat3<S>::Identity()).norm() <= tolerance);
  ALOFT_CHECK(vectors.determinant() > S(0));
}

template <typename S>
void check_spectra(S tolerance, Method method = Method::two_sided) {
  const aloft::Quat<S> frames[] = {aloft::Quat<S>::Identity(),
                                   aloft::quat_wxyz(S(0.8), S(0.2), S(-0.5), S(0.26)),
                                   aloft::quat_wxyz(S(0.1), S(0.9), S(0.3), S(-0.2))};
  for (const auto& frame : frames) {
    check_decomposition<S>(Vec3<S>(S(3), S(1), S(2)), frame, tolerance, method);
    // The paper's GF cylinder: two equal moments.
    check_decomposition<S>(Vec3<S>(S(0.0183892), S(0.0183892), S(0.0210806)), frame, tolerance, method);
    // Nearly equal moments, and all equal (a sphere).
    check_decomposition<S>(Vec3<S>(S(1), S(1.0001), S(1.5)), frame, tolerance, method);
    check_decomposition<S>(Vec3<S>(S(2), S(2), S(2)), frame, tolerance, method);
    // A widely spread spectrum (a thin rod).
    check_decomposition<S>(Vec3<S>(S(1e-4), S(1), S(1)), frame, tolerance, method);
  }
}

}  // namespace

ALOFT_TEST_CASE("Jacobi eigen-decomposition of symmetric 3x3 matrices", "[inertia]") {
  check_spectra<double>(1e-14);
  check_spectra<float>(2e-6f);
}

ALOFT_TEST_CASE("One-sided Jacobi through the Cholesky factor of positive definite 3x3 matrices",
                "[inertia]") {
  check_spectra<double>(1e-14, Method::through_cholesky);
  check_spectra<float>(2e-6f, Method::through_cholesky);
}

ALOFT_TEST_CASE("A matrix that is not positive definite has no Cholesky factor", "[inertia]") {
  const Mat3<double> r = aloft::quat_wxyz(0.8, 0.2, -0.5, 0.26).normalized().toRotationMatrix();
  Vec3<double> values = Vec3<double>::Zero();
  Mat3<double> vectors = Mat3<double>::Zero();
  for (const Vec3<double>& spectrum : {Vec3<double>(-1e-3, 1, 2), Vec3<double>(-3, -1, 2)}) {
    const Mat3<double> a = r * spectrum.asDiagonal() * r.transpose();
    ALOFT_CHECK(!aloft::positive_definite_eigen_decomposition(a, values, vectors));
  }
  // The control: the same frame with a positive spectrum decomposes.
  const Mat3<double> a = r * Vec3<double>(1e-3, 1, 2).asDiagonal() * r.transpose();
  ALOFT_CHECK(aloft::positive_definite_eigen_decomposition(a, values, vectors));
}
