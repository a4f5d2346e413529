// The hand-written Jacobi elliptic functions and K(m) used by the exact asymmetric top
// (tests/core/exact_tops.hpp) agree with Boost.Math's.
#include <catch2/catch.hpp>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>

#include "exact_tops.hpp"

TEST_CASE("sn, cn, dn and K match Boost.Math", "[exact]") {
  for (double modulus_squared : {0.0, 0.1, 0.5, 0.9, 0.999, 0.999999}) {
    // Both sides get the same m = k*k exactly: near m = 1, K is very sensitive to 1 - m.
    const double k = std::sqrt(modulus_squared);
    const double m = k * k;
    // Boost forms 1 - m from k itself; the rounding of that difference, relative
    // eps / (1 - m), is what K inherits near m = 1 (measured: the hand-written AGM agrees
    // with a long-double AGM to 1e-15 there, Boost to 1.3e-12).
    const double k_tolerance = 1e-12 + 1e-16 / (1.0 - m + 1e-300) * boost::math::ellint_1(k);
    CHECK(std::abs(aloft_test::complete_elliptic_k(m) - boost::math::ellint_1(k)) < k_tolerance);
    for (double u = -7.0; u <= 7.0; u += 0.37) {
      double cn = 0.0;
      double dn = 0.0;
      const double sn = boost::math::jacobi_elliptic(k, u, &cn, &dn);
      const aloft_test::JacobiElliptic mine = aloft_test::jacobi_elliptic(u, m);
      CHECK(std::abs(mine.sn - sn) < 1e-12);
      CHECK(std::abs(mine.cn - cn) < 1e-12);
      CHECK(std::abs(mine.dn - dn) < 1e-12);
    }
  }
}
