// Runs only under expect_failure.cmake: proves that a failing check fails the bare-metal
// run (exit status 1 out of QEMU) and that ALOFT_REQUIRE leaves its test case from inside
// a helper function. The expected summary line is in CMakeLists.txt.
#include "test_api.hpp"

namespace {

int evaluated_after_require = 0;

void helper_that_requires(bool condition) {
  ALOFT_REQUIRE(condition);
  ++evaluated_after_require;
}

}  // namespace

ALOFT_TEST_CASE("a passing case", "[runner]") { ALOFT_CHECK(1 + 1 == 2); }

ALOFT_TEST_CASE("two failed checks, both counted", "[runner]") {
  ALOFT_CHECK(1 + 1 == 3);
  ALOFT_CHECK(false);
}

ALOFT_TEST_CASE("a failed require leaves the case", "[runner]") {
  helper_that_requires(false);
  ALOFT_CHECK(evaluated_after_require == 1);  // never evaluated: the case was left
}
