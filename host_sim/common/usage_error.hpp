// The command line's one contract for a refused command line: one line on stderr that
// names the command, the bad word and the valid choices, and exit code 2. CLI11's own
// messages ("A subcommand is required", exit 104-109) are turned into that line here,
// in one place, for every command.
#pragma once

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace aloft::host {

// "aloft simulate: unknown option --bdy (did you mean --body?); options: --body, ...".
std::string usage_error_line(const CLI::App& app, const CLI::ParseError& error);

// The same line for a first word that names no command, or nothing when it names one (or
// is an option). Checked before CLI11 parses, because CLI11 answers `aloft frobnicate
// --help` with the program's help and exit 0, so a typo would pass for success.
std::optional<std::string> unknown_command(const CLI::App& app, int argc, const char* const* argv);

// Parses the command line under that contract: nothing when the program goes on, else the
// code to exit with (0 after --help or --version, 2 after the one line on stderr).
std::optional<int> parse_command_line(CLI::App& app, int argc, const char* const* argv);

}  // namespace aloft::host
