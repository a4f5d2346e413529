// Host program: `aloft replay --fifo`'s own code path (host_sim/replay: the FIFO reader,
// the body settings, run_replay) on a body file and a FIFO file, printing each flight as
// the STM32F405 replay image prints it (port/cortex_m/flight_lines.hpp).
// The image's output must equal this one (tests/stm32f405), and this one must agree with
// `aloft replay --fifo --json` (tests/replay_fifo).
//   fifo_replay_lines BODY.json FIFO.bin ODR_HZ
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "common/body_file.hpp"
#include "flight_lines.hpp"
#include "replay/fifo_recording.hpp"
#include "replay/replay_run.hpp"

namespace {
void write_stdout(const char* text) { std::fputs(text, stdout); }
}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: fifo_replay_lines BODY.json FIFO.bin ODR_HZ\n");
    return 2;
  }
  try {
    const aloft::host::Body body = aloft::host::read_body_file(argv[1]);
    const aloft::host::Recording recording = aloft::host::read_fifo_recording(argv[2], std::atof(argv[3]));
    const aloft::host::ReplayResult result =
        aloft::host::run_replay(aloft::host::replay_settings_from_body(body), argv[1], recording);
    aloft::port::ReportWriter out(write_stdout);
    out.text("aloft replay host: OnboardPipeline<float, 8>, FIFO file ").text(argv[2]).line();
    for (const aloft::FlightResult<float>& f : result.flights) {
      aloft_flight_lines::write_flight_lines(out, f, result.t0_us);
    }
    out.text("stream_samples ").integer(result.stream.samples).line();
    out.text("stream_gaps ").integer(result.stream.gaps).line();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fifo_replay_lines: %s\n", e.what());
    return 2;
  }
  return 0;
}
