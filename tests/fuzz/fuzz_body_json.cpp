// libFuzzer harness: the body file reader on arbitrary bytes (see fuzz_input.hpp).
#include "fuzz_input.hpp"
#include "common/body_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  aloft::fuzz::read_input(data, size, ".json",
                          [](const std::string& path) { aloft::host::read_body_file(path); });
  return 0;
}
