// libFuzzer harness: the OpenSim .mot/.sto reader on arbitrary bytes (see fuzz_input.hpp).
#include "fuzz_input.hpp"
#include "readers/pose_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  aloft::fuzz::read_input(data, size, ".mot", [](const std::string& path) { aloft::host::read_mot(path); });
  return 0;
}
