// aloft: the host program. Each command lives in its own folder and registers itself
// here; main only dispatches, and keeps the command line's contract: a refused command
// line or a failed command is one line on stderr and exit code 2.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "common/commands.hpp"
#include "common/usage_error.hpp"
#include "records/records_command.hpp"
#include "summarize/summarize_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"aloft: validate a rigid body's inertia tensor by throwing it", "aloft"};
  app.set_version_flag("--version", "aloft " ALOFT_VERSION);
  app.require_subcommand(1);
  aloft::host::add_simulate_command(app);
  aloft::host::add_study_command(app);
  aloft::host::add_inspect_command(app);
  aloft::host::add_diagnose_command(app);
  aloft::host::add_replay_command(app);
  aloft::host::add_records_command(app);
  aloft::host::add_summarize_command(app);
  if (const auto unknown = aloft::host::unknown_command(app, argc, argv)) {
    std::fprintf(stderr, "%s\n", unknown->c_str());
    return 2;
  }
  try {  // the commands run inside the parse
    if (const auto code = aloft::host::parse_command_line(app, argc, argv)) return *code;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "aloft: %s\n", e.what());
    return 2;
  }
  return aloft::host::exit_code();
}
