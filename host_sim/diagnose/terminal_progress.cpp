#include "diagnose/terminal_progress.hpp"

#include <chrono>
#include <cstdio>

#include <unistd.h>

namespace aloft::host::diagnose {

ParallelProgress terminal_flight_progress() {
  ParallelProgress progress;
  if (!::isatty(STDERR_FILENO)) return progress;
  const auto start = std::chrono::steady_clock::now();
  progress.report = [start](std::size_t done, std::size_t total) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (done == total) {
      std::fprintf(stderr, "\r\033[Kdiagnose: %zu / %zu flights; the pooled analysis...", done, total);
    } else if (done == 0) {
      std::fprintf(stderr, "\r\033[Kdiagnose: 0 / %zu flights", total);
    } else {
      const double left = elapsed / static_cast<double>(done) * static_cast<double>(total - done);
      std::fprintf(stderr,
                   "\r\033[Kdiagnose: %zu / %zu flights, about %.0f s left before the pooled analysis", done,
                   total, left);
    }
    std::fflush(stderr);
  };
  return progress;
}

void clear_terminal_progress() {
  if (!::isatty(STDERR_FILENO)) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
}

}  // namespace aloft::host::diagnose
