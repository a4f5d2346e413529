// Host program: `aloft replay`'s own code path (host_sim/replay: the CSV reader, the body
// settings, run_replay) on a body file and an IMU CSV, printing each flight as the replay
// firmware prints it (port/cortex_m/flight_lines.hpp). The firmware's output must equal this one
// (tests/target), and this one must agree with `aloft replay --json` (tests/replay).
//   replay_lines BODY.json IMU.csv
#include <cstdio>
#include <exception>

#include "common/body_file.hpp"
#include "flight_lines.hpp"
#include "replay/imu_csv_recording.hpp"
#include "replay/replay_run.hpp"

namespace {
void write_stdout(const char* text) { std::fputs(text, stdout); }
}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: replay_lines BODY.json IMU.csv\n");
    return 2;
  }
  try {
    const aloft::host::Body body = aloft::host::read_body_file(argv[1]);
    const aloft::host::Recording recording = aloft::host::read_imu_csv_recording(argv[2]);
    const aloft::host::ReplayResult result =
        aloft::host::run_replay(aloft::host::replay_settings_from_body(body), argv[1], recording);
    aloft::port::ReportWriter out(write_stdout);
    out.text("aloft replay host: OnboardPipeline<float, 8>, recording ").text(argv[2]).line();
    for (const aloft::FlightResult<float>& f : result.flights) {
      aloft_flight_lines::write_flight_lines(out, f, result.t0_us);
    }
    out.text("stream_samples ").integer(result.stream.samples).line();
    out.text("stream_gaps ").integer(result.stream.gaps).line();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "replay_lines: %s\n", e.what());
    return 2;
  }
  return 0;
}
