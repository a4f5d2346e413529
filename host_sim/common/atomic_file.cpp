#include "common/atomic_file.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "common/commands.hpp"

namespace aloft::host {

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  // Same folder as the target, so the final rename never crosses file systems.
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code ec;
  if (!folder.empty() && !std::filesystem::create_directories(folder, ec) && ec) {
    throw Error(path + ": cannot make folder " + folder.string() + " (" + ec.message() + ")");
  }
  try {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw Error(path + ": cannot open for writing");
    write(out);
    out.flush();
    if (!out) throw Error(path + ": write failed");
    out.close();
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
      throw Error(path + ": cannot move the finished file into place");
    }
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
}

}  // namespace aloft::host
