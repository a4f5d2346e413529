// libFuzzer harness: the record-dump reader of `aloft records` on arbitrary bytes (see
// fuzz_input.hpp).
#include "fuzz_input.hpp"
#include "records/record_dump.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  aloft::fuzz::read_input(data, size, ".bin",
                          [](const std::string& path) { aloft::host::read_record_dump(path); });
  return 0;
}
