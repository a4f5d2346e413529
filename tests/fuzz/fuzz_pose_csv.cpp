// libFuzzer harness: the pose CSV reader on arbitrary bytes (see fuzz_input.hpp).
#include "fuzz_input.hpp"
#include "readers/pose_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  aloft::fuzz::read_input(data, size, ".csv",
                          [](const std::string& path) { aloft::host::read_pose_csv(path); });
  return 0;
}
