// Placeholder until the study issue lands: says so and fails.
#include "common/commands.hpp"

namespace aloft::host {
void add_study_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("study", "the paper's cylinder study (not yet implemented)");
  cmd->allow_extras();
  cmd->callback([] { throw Error("study: not implemented yet"); });
}
}  // namespace aloft::host
