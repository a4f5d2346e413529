// What every libFuzzer harness of tests/fuzz does with an input: the readers take a
// path, so the bytes go to a file of this process (with the extension that selects the
// reader), the reader runs, and aloft::host::Error — a refusal, the expected outcome for
// most inputs — is the only exception let pass. Anything else escaping (a library's
// exception, std::bad_alloc, a crash, a sanitizer report) is a finding: libFuzzer stops
// and saves the input. Warnings are captured so the fuzzer's output stays readable.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <string>

#include "common/commands.hpp"
#include "common/warning.hpp"

namespace aloft::fuzz {

inline std::string input_path(const std::string& extension) {
  return "/tmp/aloft-fuzz-" + std::to_string(::getpid()) + extension;
}

template <typename Read>
void read_input(const std::uint8_t* data, std::size_t size, const std::string& extension, Read&& read) {
  const std::string path = input_path(extension);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  const aloft::host::WarningCapture quiet;
  try {
    read(path);
  } catch (const aloft::host::Error&) {
    // A refusal with aloft's one line: what hostile input should get.
  }
}

}  // namespace aloft::fuzz
