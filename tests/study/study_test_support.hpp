// Running the built `aloft` program from a test, in a fresh temporary folder, and
// reading back what it wrote.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

namespace aloft::test {

class StudyScratch {
 public:
  StudyScratch() {
    std::string pattern = (std::filesystem::temp_directory_path() / "aloft-study-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    dir_ = pattern;
  }
  ~StudyScratch() {
    std::error_code ignored;
    std::filesystem::remove_all(dir_, ignored);
  }
  StudyScratch(const StudyScratch&) = delete;
  StudyScratch& operator=(const StudyScratch&) = delete;

  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::string write(const std::string& name, const std::string& content) const {
    std::ofstream(path(name), std::ios::binary) << content;
    return path(name);
  }

 private:
  std::filesystem::path dir_;
};

struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `aloft ARGS` with stdout and stderr captured into files of `scratch`.
inline RunResult run_aloft(const StudyScratch& scratch, const std::string& args) {
  const std::string out = scratch.path("stdout.txt"), err = scratch.path("stderr.txt");
  const std::string command =
      std::string("'") + ALOFT_EXECUTABLE + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int status = std::system(command.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

inline std::size_t count_lines(const std::string& text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

inline std::string shared_data_dir() {
  const std::filesystem::path dir = std::filesystem::path(ALOFT_SHARED_DIR) / "data";
  return std::filesystem::is_directory(dir) ? dir.string() : std::string();
}

}  // namespace aloft::test
