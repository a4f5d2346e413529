// Placeholder until the diagnose issue lands: says so and fails.
#include "common/commands.hpp"

namespace aloft::host {
void add_diagnose_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("diagnose", "diagnose the sim-to-real gap (not yet implemented)");
  cmd->allow_extras();
  cmd->callback([] { throw Error("diagnose: not implemented yet"); });
}
}  // namespace aloft::host
