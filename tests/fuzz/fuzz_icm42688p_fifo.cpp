// libFuzzer harness: the ICM-42688-P FIFO file reader of `replay --fifo` (and through it
// the firmware's packet decoder) on arbitrary bytes (see fuzz_input.hpp).
#include "fuzz_input.hpp"
#include "replay/fifo_recording.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  aloft::fuzz::read_input(data, size, ".bin",
                          [](const std::string& path) { aloft::host::read_fifo_recording(path, 1000); });
  return 0;
}
