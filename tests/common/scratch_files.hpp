// Test fixtures written on the fly: a fresh temporary folder per test and small files in
// it, so no data file is committed and each bad-input case is visible in its test.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <catch2/catch.hpp>

namespace aloft::test {

class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "aloft-test-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    dir_ = pattern;
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  // Writes `content` byte for byte to NAME in the folder and returns its path.
  std::string write(const std::string& name, const std::string& content) const {
    const std::string path = (dir_ / name).string();
    std::ofstream out(path, std::ios::binary);
    out << content;
    return path;
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::filesystem::path dir_;
};

// The shared data folder (../shared/data), or "" when this checkout has none.
inline std::string shared_data_dir() {
  const std::filesystem::path dir = std::filesystem::path(ALOFT_SHARED_DIR) / "data";
  return std::filesystem::is_directory(dir) ? dir.string() : std::string();
}

}  // namespace aloft::test

// Skips the rest of a test case, saying why, when ../shared is not there.
#define ALOFT_REQUIRE_SHARED_DATA(dir_var)                                           \
  const std::string dir_var = aloft::test::shared_data_dir();                        \
  if (dir_var.empty()) {                                                             \
    WARN("skipped: ../shared/data not found (" ALOFT_SHARED_DIR "); test needs it"); \
    return;                                                                          \
  }
