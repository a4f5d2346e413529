// libFuzzer harness: the OpenSim model reader (--osim, --joint j) on arbitrary bytes (see fuzz_input.hpp).
#include "fuzz_input.hpp"
#include "readers/osim_joint.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  aloft::fuzz::read_input(data, size, ".osim",
                          [](const std::string& path) { aloft::host::read_osim_joint(path, "j"); });
  return 0;
}
