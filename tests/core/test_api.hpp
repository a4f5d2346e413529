// The few test macros the core test bodies use, so the same bodies run under Catch2
// (host and armhf) and under the no-heap bare-metal runner (cortex-m4f), which
// defines ALOFT_BARE_METAL_RUNNER and supplies its own definitions.
//   ALOFT_TEST_CASE(name, tags)  a test case
//   ALOFT_CHECK(expr)            record a failure and go on (variadic: template commas)
//   ALOFT_REQUIRE(expr)          record a failure and leave the test case
// Float and double are covered by writing a body as a function template and calling
// it for both from one test case (the runner has no template test cases).
#pragma once

#if defined(ALOFT_BARE_METAL_RUNNER)
#include "bare_metal_runner.hpp"
#else
#include <catch2/catch.hpp>
#define ALOFT_TEST_CASE(name, tags) TEST_CASE(name, tags)
#define ALOFT_CHECK(...) CHECK(__VA_ARGS__)
#define ALOFT_REQUIRE(...) REQUIRE(__VA_ARGS__)
#endif
