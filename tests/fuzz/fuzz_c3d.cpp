// libFuzzer harness: the C3D reader on arbitrary bytes (see fuzz_input.hpp).
#include "fuzz_input.hpp"
#include "readers/c3d_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  aloft::fuzz::read_input(data, size, ".c3d", [](const std::string& path) {
    aloft::host::C3dDetails details;  // damage reported here, not on stderr
    aloft::host::read_c3d(path, &details);
  });
  return 0;
}
