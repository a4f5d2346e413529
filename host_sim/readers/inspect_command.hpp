// `aloft inspect` (readers/inspect_command.cpp): its options and the summary it prints,
// shared by the command and the Python module (aloft.inspect).
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>

#include "readers/free_joint.hpp"
#include "readers/imu_units.hpp"

namespace aloft::host {

struct InspectOptions {
  std::string file;
  std::string body;       // --body: a body file, for marker files only
  std::string body_json;  // the body's content when handed over in memory (body names it)
  PoseNaming naming;
  ImuUnits units;
};

// The file and --body, --pose-*, --osim, --joint and the unit options on `command`.
void add_inspect_options(CLI::App& command, InspectOptions& options);

// The JSON summary `aloft inspect` prints; throws Error on a file it cannot summarise.
nlohmann::ordered_json inspect_summary(const InspectOptions& options);

}  // namespace aloft::host
