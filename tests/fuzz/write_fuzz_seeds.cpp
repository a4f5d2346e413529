// write_fuzz_seeds DIR: writes the seed corpus of every harness into DIR/<harness>/.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "fuzz_seeds.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_fuzz_seeds DIR\n");
    return 2;
  }
  for (const auto& [harness, seeds] : aloft::fuzz::seed_corpus()) {
    const std::filesystem::path dir = std::filesystem::path(argv[1]) / harness;
    std::filesystem::create_directories(dir);
    for (const auto& seed : seeds) std::ofstream(dir / seed.name, std::ios::binary) << seed.bytes;
  }
  return 0;
}
