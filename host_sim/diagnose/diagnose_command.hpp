// `aloft diagnose` (diagnose/diagnose_command.cpp): its options and the report it writes,
// shared by the command and the Python module (aloft.diagnose).
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

#include "readers/free_joint.hpp"
#include "readers/imu_units.hpp"

namespace aloft::host {

struct DiagnoseOptions {
  std::string body;
  std::string body_json;  // the body's content when handed over in memory (body names it)
  std::string imu, segments, window, markers, poses;
  ImuUnits imu_units;      // --time-units, --gyro-units, --accel-units
  PoseNaming pose_naming;  // --pose-columns / --osim --joint for a .mot/.sto
  std::string json, plot, corrected_body;
  int threads = 0;  // 0: every core, as aloft study
};

// Every option of `aloft diagnose` on `command`.
void add_diagnose_options(CLI::App& command, DiagnoseOptions& options);

// Where the command's words go: the summary (null: none), and whether a session shows its
// progress on a terminal.
struct DiagnoseOutput {
  std::ostream* summary = nullptr;
  bool terminal_progress = false;
};

// The diagnosis the options ask for: its report, as --json writes it; the --json file,
// the plots and the corrected body written where asked, once all is computed. Throws
// Error on bad input.
nlohmann::json diagnose_report(const DiagnoseOptions& options, const DiagnoseOutput& output);

}  // namespace aloft::host
