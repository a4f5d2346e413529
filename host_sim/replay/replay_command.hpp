// `aloft replay` (replay/replay_command.cpp): its options and the run its reports are
// made of, shared by the command and the Python module (aloft.replay).
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "readers/imu_units.hpp"
#include "replay/recording.hpp"
#include "replay/replay_run.hpp"

namespace aloft::host {

struct ReplayOptions {
  std::string body_path;
  std::string body_json;  // the body's content when handed over in memory (body_path names it)
  std::string imu_path;
  ImuUnits imu_units;  // --time-units, --gyro-units, --accel-units
  std::string fifo_path;
  double odr_hz = 0.0;
  int gyro_filter_us = -1;  // --gyro-filter-us; -1: the firmware's setting (tensor.gyro_filter_us)
  std::string json_path;
};

// --body, --imu | --fifo with --odr-hz, the unit options, --gyro-filter-us and --json on
// `command`.
void add_replay_options(CLI::App& command, ReplayOptions& options);

// The recording read and the pipeline run over it: what replay_report_json and
// replay_report_text report. Throws Error on bad input.
struct ReplayRun {
  Recording recording;
  ReplayResult result;
};
ReplayRun run_replay_options(const ReplayOptions& options);

}  // namespace aloft::host
