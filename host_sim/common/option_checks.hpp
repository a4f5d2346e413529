// Checks that CLI11 runs on option values while it parses the command line, so a bad
// value is refused before a command does any work (and reported by usage_error_line).
#pragma once

#include <CLI/CLI.hpp>

namespace aloft::host {

// A whole number >= 0 written in digits: "-1" is refused rather than wrapped round to
// 18446744073709551615 by an unsigned conversion.
CLI::Validator whole_number();

// A file the command will write: not an existing directory, writable itself if it
// exists, and in a folder that output_folder() accepts (missing folders are made).
CLI::Validator output_file();

// A folder the command will write into (created if needed): not an existing file, and
// writable, or else creatable under the nearest folder that exists.
CLI::Validator output_folder();

}  // namespace aloft::host
