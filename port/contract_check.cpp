// Exercises a port's contract (aloft_port/port.hpp) end to end: the clock advances, text
// reaches the output, and the exit status reaches whoever ran the program. Exits with 3,
// not 0, so a port whose exit_with_status ignores the status is caught.
#include "aloft_port/report_writer.hpp"

int main() {
  aloft::port::init();
  aloft::port::ReportWriter out;
  const std::uint64_t start = aloft::port::ticks();
  volatile std::uint32_t spin = 0;
  while (aloft::port::ticks() == start) spin = spin + 1u;
  const std::uint64_t later = aloft::port::ticks();
  out.text("port contract: ticks advance ")
      .text(later > start ? "yes" : "NO")
      .text(", ")
      .integer(aloft::port::ticks_per_second())
      .text(" per second")
      .line();
  aloft::port::exit_with_status(later > start ? 3 : 1);
}
