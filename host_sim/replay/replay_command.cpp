// `aloft replay` (SPEC §5): the firmware's onboard pipeline, in float, on a recording,
// sample by sample; it finds the flights itself. The table goes to stdout; --json writes
// the report (replay_report_json.hpp) whole or not at all.
//   aloft replay --body BODY.json (--imu LOG.csv | --fifo FIFO.bin --odr-hz N)
//                [--gyro-filter-us US] [--json R]
#include <cstdio>
#include <memory>
#include <string>

#include "common/json_text.hpp"
#include "common/atomic_file.hpp"
#include "common/body_file.hpp"
#include "common/commands.hpp"
#include "common/option_checks.hpp"
#include "readers/accel_at_rest.hpp"
#include "readers/imu_csv_reader.hpp"
#include "readers/imu_units.hpp"
#include "replay/fifo_recording.hpp"
#include "replay/imu_csv_recording.hpp"
#include "replay/replay_command.hpp"
#include "replay/replay_report_json.hpp"
#include "replay/replay_report_text.hpp"
#include "replay/replay_run.hpp"
#include "replay/rotor_match.hpp"

namespace aloft::host {
namespace {

Recording read_recording(const ReplayOptions& o) {
  if (!o.imu_path.empty()) {
    ImuLog log = read_imu_csv(o.imu_path);
    convert_to_si(log, o.imu_units);
    check_accel_units(log);  // a log in g would look like one long free fall
    return imu_csv_recording(log);
  }
  return read_fifo_recording(o.fifo_path, o.odr_hz);
}

void run_replay_command(const ReplayOptions& o) {
  const ReplayRun run = run_replay_options(o);
  const Recording& recording = run.recording;
  const ReplayResult& result = run.result;
  if (!o.json_path.empty()) {
    const nlohmann::json report = replay_report_json(recording, result);
    write_file_atomically(o.json_path, [&](std::ostream& out) { out << json_text(report) << '\n'; });
  }
  std::fputs(replay_report_text(recording, result).c_str(), stdout);
}

}  // namespace

ReplayRun run_replay_options(const ReplayOptions& o) {
  const Body body = read_body(o.body_path, o.body_json);
  ReplayRun run;
  run.recording = read_recording(o);
  check_rotor_matches(body, o.body_path, run.recording);
  ReplaySettings settings = replay_settings_from_body(body);
  const bool told = o.gyro_filter_us >= 0;
  if (told) settings.gyro_filter_us = static_cast<std::uint16_t>(o.gyro_filter_us);
  run.result = run_replay(settings, o.body_path, run.recording);
  run.result.gyro_filter_from_option = told;
  return run;
}

void add_replay_options(CLI::App& command, ReplayOptions& options) {
  CLI::App* cmd = &command;
  cmd->add_option("--body", options.body_path,
                  "body file (JSON: docs/file-formats.md); imu.position, if given, is used")
      ->required();
  CLI::Option_group* input = cmd->add_option_group("input", "the recording: exactly one of");
  input->add_option("--imu", options.imu_path, "plain IMU log t,gx,gy,gz,ax,ay,az (s, rad/s, m/s^2)");
  add_imu_unit_options(*cmd, options.imu_units);
  CLI::Option* fifo =
      input->add_option("--fifo", options.fifo_path, "ICM-42688-P FIFO bytes (docs/file-formats.md)");
  input->require_option(1);
  cmd->add_option("--odr-hz", options.odr_hz, "the FIFO's output data rate, Hz (with --fifo)")
      ->needs(fifo)
      ->type_name("HZ")
      ->check(CLI::PositiveNumber.description(""));
  fifo->needs(cmd->get_option("--odr-hz"));
  cmd->add_option("--gyro-filter-us", options.gyro_filter_us,
                  "the time constant of the gyro's first-order low-pass in the firmware that logged the "
                  "recording, µs (0: none); default: aloft's firmware's, 640 (the ICM-42688-P's UI filter "
                  "at a quarter of 1 kHz)")
      ->type_name("US")
      ->check(CLI::Range(0, 65535).description(""));
  cmd->add_option("--json", options.json_path, "write the report as JSON (keys: docs/file-formats.md)")
      ->check(output_file());
}

void add_replay_command(CLI::App& app) {
  auto options = std::make_shared<ReplayOptions>();
  CLI::App* cmd = app.add_subcommand(
      "replay", "run the firmware's onboard pipeline (float) on a recording; finds the flights");
  add_replay_options(*cmd, *options);
  cmd->callback([options] { run_replay_command(*options); });
}

}  // namespace aloft::host
