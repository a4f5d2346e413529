// Host program: the replay firmware's lines (port/cortex_m/replay_example) for a body file
// and an IMU CSV, through `aloft replay`'s own CSV reader (replay_lines.hpp). The
// firmware's output must equal this one (tests/target), and this one must agree with
// `aloft replay --json` (tests/replay).
//   replay_lines BODY.json IMU.csv
#include <cstdio>

#include "replay/imu_csv_recording.hpp"
#include "replay_lines.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: replay_lines BODY.json IMU.csv\n");
    return 2;
  }
  return aloft_replay_lines::print_replay_lines("replay_lines", argv[1], "recording", argv[2],
                                                [&] { return aloft::host::read_imu_csv_recording(argv[2]); });
}
