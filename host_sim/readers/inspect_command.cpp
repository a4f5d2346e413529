// Placeholder until the inspect issue lands: says so and fails.
#include "common/commands.hpp"

namespace aloft::host {
void add_inspect_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("inspect", "summarise a trial file (not yet implemented)");
  cmd->allow_extras();
  cmd->callback([] { throw Error("inspect: not implemented yet"); });
}
}  // namespace aloft::host
