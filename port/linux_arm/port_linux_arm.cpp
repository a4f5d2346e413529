// The platform contract (aloft_port/port.hpp) on embedded Linux (armhf boards, and
// qemu-arm in the tests) with plain POSIX calls: no stdio buffering between the program
// and a serial console, and a monotonic clock unaffected by NTP steps.
#include <time.h>
#include <unistd.h>

#include <cstring>

#include "aloft_port/port.hpp"

namespace aloft {
namespace port {

namespace {
std::uint64_t start_ns = 0;

std::uint64_t monotonic_ns() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<std::uint64_t>(now.tv_sec) * 1000000000u + static_cast<std::uint64_t>(now.tv_nsec);
}
}  // namespace

void init() { start_ns = monotonic_ns(); }

std::uint64_t ticks() { return monotonic_ns() - start_ns; }

std::uint32_t ticks_per_second() { return 1000000000u; }

void write_text(const char* text) {
  std::size_t left = std::strlen(text);
  while (left > 0) {
    const ssize_t written = write(STDOUT_FILENO, text, left);
    if (written <= 0) return;  // nowhere to report a failed report
    text += written;
    left -= static_cast<std::size_t>(written);
  }
}

void exit_with_status(int status) { _exit(status); }

}  // namespace port
}  // namespace aloft
