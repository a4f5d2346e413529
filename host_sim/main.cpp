// aloft: the host program. Each command lives in its own folder and registers itself
// here; main only dispatches and turns an escaped error into one line and exit code 2.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "common/commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"aloft: validate a rigid body's inertia tensor by throwing it"};
  app.require_subcommand(1);
  aloft::host::add_simulate_command(app);
  aloft::host::add_study_command(app);
  aloft::host::add_inspect_command(app);
  aloft::host::add_diagnose_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "aloft: %s\n", e.what());
    return 2;
  }
  return aloft::host::exit_code();
}
