// Host program: the STM32F405 replay image's lines for a body file and a FIFO file, through
// `aloft replay --fifo`'s own FIFO reader (replay_lines.hpp). The image's output must equal
// this one (tests/stm32f405), and this one must agree with `aloft replay --fifo --json`
// (tests/replay_fifo).
//   fifo_replay_lines BODY.json FIFO.bin ODR_HZ
#include <cstdio>
#include <cstdlib>

#include "replay/fifo_recording.hpp"
#include "replay_lines.hpp"

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: fifo_replay_lines BODY.json FIFO.bin ODR_HZ\n");
    return 2;
  }
  return aloft_replay_lines::print_replay_lines("fifo_replay_lines", argv[1], "FIFO file", argv[2], [&] {
    return aloft::host::read_fifo_recording(argv[2], std::atof(argv[3]));
  });
}
