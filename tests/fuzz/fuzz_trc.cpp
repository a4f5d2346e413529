// libFuzzer harness: the TRC reader on arbitrary bytes (see fuzz_input.hpp).
#include "fuzz_input.hpp"
#include "readers/trc_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  aloft::fuzz::read_input(data, size, ".trc", [](const std::string& path) { aloft::host::read_trc(path); });
  return 0;
}
