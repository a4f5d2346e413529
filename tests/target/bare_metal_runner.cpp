// The bare-metal runner's registry and main (see bare_metal_runner.hpp).
#include "bare_metal_runner.hpp"

#include <csetjmp>
#include <cstdint>

#include "aloft_port/report_writer.hpp"

#ifndef ALOFT_MAX_TEST_CASES
#define ALOFT_MAX_TEST_CASES 128
#endif

namespace aloft_test_runner {

namespace {

struct TestCase {
  TestFunction function;
  const char* name;
  const char* tags;
  const char* file;
  int line;
};

// Zero-initialised before any registration object's constructor runs.
TestCase test_cases[ALOFT_MAX_TEST_CASES];
int test_case_count = 0;
bool registry_overflowed = false;

std::uint32_t checks_evaluated = 0;
std::uint32_t checks_failed = 0;
std::jmp_buf test_case_exit;

aloft::port::ReportWriter out;

}  // namespace

Registration::Registration(TestFunction function, const char* name, const char* tags, const char* file,
                           int line) {
  if (test_case_count == ALOFT_MAX_TEST_CASES) {
    registry_overflowed = true;
    return;
  }
  test_cases[test_case_count++] = TestCase{function, name, tags, file, line};
}

bool check(bool passed, const char* file, int line, const char* expression) {
  ++checks_evaluated;
  if (!passed) {
    ++checks_failed;
    out.text(file).text(":").integer(line).text(": FAILED: ").text(expression).line();
  }
  return passed;
}

void abandon_test_case() { std::longjmp(test_case_exit, 1); }

int run_all_test_cases() {
  if (registry_overflowed) {
    out.text("more than ")
        .integer(ALOFT_MAX_TEST_CASES)
        .text(" test cases: raise ALOFT_MAX_TEST_CASES")
        .line();
    return 2;
  }
  if (test_case_count == 0) {
    out.text("no test cases registered").line();
    return 2;
  }
  int failed_cases = 0;
  for (int i = 0; i < test_case_count; ++i) {
    const TestCase& test = test_cases[i];
    const std::uint32_t failures_before = checks_failed;
    const std::uint32_t checks_before = checks_evaluated;
    const std::uint64_t start = aloft::port::ticks();
    if (setjmp(test_case_exit) == 0) {
      test.function();
    }
    const std::uint64_t elapsed = aloft::port::ticks() - start;
    const bool passed = checks_failed == failures_before;
    if (!passed) ++failed_cases;
    const std::uint64_t ms = elapsed * 1000u / aloft::port::ticks_per_second();
    out.text(passed ? "[  OK  ] " : "[FAILED] ")
        .text(test.name)
        .text(" ")
        .text(test.tags)
        .text(" (")
        .integer(static_cast<std::int64_t>(checks_evaluated - checks_before))
        .text(" checks, ")
        .integer(static_cast<std::int64_t>(ms))
        .text(" ms)")
        .line();
  }
  out.text(failed_cases == 0 ? "PASSED: " : "FAILED: ")
      .integer(test_case_count - failed_cases)
      .text(" of ")
      .integer(test_case_count)
      .text(" test cases passed, ")
      .integer(checks_evaluated)
      .text(" checks evaluated, ")
      .integer(checks_failed)
      .text(" failed")
      .line();
  return failed_cases == 0 ? 0 : 1;
}

}  // namespace aloft_test_runner

int main() {
  aloft::port::init();
  return aloft_test_runner::run_all_test_cases();
}
