// Running the built `aloft` program (ALOFT_PROGRAM, set by the test's CMakeLists) from a
// test, in a fresh temporary folder, and reading back what it wrote. One copy for every
// test program that runs aloft as a user would.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "scratch_files.hpp"

namespace aloft::test {

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

inline void write_file(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// A scratch folder for the whole test program, removed when it ends.
inline const ScratchDir& program_scratch() {
  static const ScratchDir scratch;
  return scratch;
}

// Runs `aloft ARGS` with stdout and stderr captured into files of `scratch`.
inline RunResult run_aloft(const ScratchDir& scratch, const std::string& args) {
  const std::string out = scratch.path("stdout.txt"), err = scratch.path("stderr.txt");
  const std::string command =
      std::string("'") + ALOFT_PROGRAM + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int status = std::system(command.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_file(out);
  r.err = read_file(err);
  return r;
}

inline RunResult run_aloft(const std::string& args) { return run_aloft(program_scratch(), args); }

inline std::size_t count_lines(const std::string& text) {
  std::size_t n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

}  // namespace aloft::test
