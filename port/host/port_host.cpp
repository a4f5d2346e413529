// The platform contract (aloft_port/port.hpp) on a desktop OS, with the C++ standard
// library only: lets the firmware-side programs run and be debugged on the host.
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "aloft_port/port.hpp"

namespace aloft {
namespace port {

namespace {
std::chrono::steady_clock::time_point start_time;
}

void init() { start_time = std::chrono::steady_clock::now(); }

std::uint64_t ticks() {
  const auto elapsed = std::chrono::steady_clock::now() - start_time;
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(elapsed).count());
}

std::uint32_t ticks_per_second() { return 1000000000u; }

void write_text(const char* text) {
  std::fputs(text, stdout);
  std::fflush(stdout);
}

void exit_with_status(int status) { std::exit(status); }

}  // namespace port
}  // namespace aloft
