// The command line's one contract for a refused command line: one line on stderr that
// names the command, the bad word and the valid choices, and exit code 2. CLI11's own
// messages ("A subcommand is required", exit 104-109) are turned into that line here,
// in one place, for every command.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace aloft::host {

// "aloft simulate: unknown option --bdy (did you mean --body?); options: --body, ...".
std::string usage_error_line(const CLI::App& app, const CLI::ParseError& error);

}  // namespace aloft::host
