// The commands of the `aloft` program. Each add_*_command registers a CLI11 subcommand
// whose callback does the work; a command reports failure by throwing aloft::host::Error
// (one line, no partial output left behind) and success by returning normally.
#pragma once

#include <CLI/CLI.hpp>

#include <cerrno>
#include <stdexcept>
#include <string>

namespace aloft::host {

// A user-facing failure: the message is printed as one line on stderr, exit code 2.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A file that cannot be opened or read (missing, not permitted, an I/O error): the same
// one line and exit code as any Error. The Python module raises OSError for it where it
// raises ValueError for any other Error; `error_number` is errno at the failure.
struct FileError : Error {
  explicit FileError(const std::string& message, int error = errno) : Error(message), error_number(error) {}
  int error_number;
};

void add_simulate_command(CLI::App& app);  // host_sim/simulate/
void add_study_command(CLI::App& app);     // host_sim/study/
void add_inspect_command(CLI::App& app);   // host_sim/readers/
void add_diagnose_command(CLI::App& app);  // host_sim/diagnose/
void add_replay_command(CLI::App& app);    // host_sim/replay/

// Exit code set by a command that succeeded with a caveat (0 unless a command sets it).
int exit_code();
void set_exit_code(int code);

}  // namespace aloft::host
