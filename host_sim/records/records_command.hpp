// `aloft records` registers here (host_sim/records/records_command.cpp).
// MERGE NOTE: this declaration belongs in host_sim/common/commands.hpp beside the other
// add_*_command; it sits apart only so that this branch's builds did not recompile every
// command while it was written.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>

#include "records/record_dump.hpp"

namespace aloft::host {

void add_records_command(CLI::App& app);  // host_sim/records/

// What `aloft records --json` prints for the dump read from `path`: {"file", "slots",
// "flights", "problems"}; shared with the Python module (aloft.records).
nlohmann::json records_json(const std::string& path, const RecordDump& dump);

}  // namespace aloft::host
