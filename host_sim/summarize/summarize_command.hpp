// `aloft summarize` (host_sim/summarize/). Declared here rather than beside the other
// commands in common/commands.hpp only to keep this branch's rebuild small: the lead
// moves the line there on merge.
#pragma once

#include <CLI/CLI.hpp>

namespace aloft::host {

void add_summarize_command(CLI::App& app);

}  // namespace aloft::host
