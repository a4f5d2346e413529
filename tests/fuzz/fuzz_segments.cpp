// libFuzzer harness: the segments reader on arbitrary bytes (see fuzz_input.hpp).
#include "fuzz_input.hpp"
#include "readers/segments.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  aloft::fuzz::read_input(data, size, ".csv",
                          [](const std::string& path) { aloft::host::read_segments_csv(path); });
  return 0;
}
