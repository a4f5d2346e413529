// A no-heap test runner for bare metal, behind the macros of tests/core/test_api.hpp:
// the core test bodies run on a Cortex-M as they do under Catch2 on the host.
//   - Each ALOFT_TEST_CASE registers itself from a static object into a fixed array (no
//     heap; the capacity is ALOFT_MAX_TEST_CASES).
//   - ALOFT_CHECK records a failure and goes on; ALOFT_REQUIRE records it and leaves the
//     test case, from any depth of helper functions, as Catch2's does. Without exceptions
//     that is a longjmp back to the runner, so destructors of the abandoned frames do not
//     run: acceptable in tests, which hold no resources on a board.
//   - Results go through aloft::port::write_text; run_all_test_cases() returns the exit
//     status, non-zero when any check failed, which the port hands to QEMU.
#pragma once

namespace aloft_test_runner {

using TestFunction = void (*)();

struct Registration {
  Registration(TestFunction function, const char* name, const char* tags, const char* file, int line);
};

// Counts one evaluated check; records a failure when it did not hold. Returns passed.
bool check(bool passed, const char* file, int line, const char* expression);

// Leaves the running test case (after a failed ALOFT_REQUIRE).
[[noreturn]] void abandon_test_case();

// Runs every registered test case and reports; returns 0 when all passed.
int run_all_test_cases();

}  // namespace aloft_test_runner

#define ALOFT_RUNNER_CONCAT_(a, b) a##b
#define ALOFT_RUNNER_CONCAT(a, b) ALOFT_RUNNER_CONCAT_(a, b)
#define ALOFT_RUNNER_TEST_CASE_(function, name, tags)                                                        \
  static void function();                                                                                    \
  static const ::aloft_test_runner::Registration ALOFT_RUNNER_CONCAT(function, _entry){function, name, tags, \
                                                                                       __FILE__, __LINE__};  \
  static void function()

#define ALOFT_TEST_CASE(name, tags) \
  ALOFT_RUNNER_TEST_CASE_(ALOFT_RUNNER_CONCAT(aloft_test_case_, __COUNTER__), name, tags)

#define ALOFT_CHECK(...) \
  static_cast<void>(     \
      ::aloft_test_runner::check(static_cast<bool>(__VA_ARGS__), __FILE__, __LINE__, #__VA_ARGS__))

#define ALOFT_REQUIRE(...)                                                                               \
  do {                                                                                                   \
    if (!::aloft_test_runner::check(static_cast<bool>(__VA_ARGS__), __FILE__, __LINE__, #__VA_ARGS__)) { \
      ::aloft_test_runner::abandon_test_case();                                                          \
    }                                                                                                    \
  } while (0)
