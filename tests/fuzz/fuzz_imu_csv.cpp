// libFuzzer harness: the IMU CSV reader (plain and phyphox) on arbitrary bytes (see fuzz_input.hpp).
#include "fuzz_input.hpp"
#include "readers/imu_csv_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  aloft::fuzz::read_input(data, size, ".csv",
                          [](const std::string& path) { aloft::host::read_imu_csv(path); });
  return 0;
}
