// diagnose, replay, records, study and inspect: each parses its arguments with the
// command's own options (command_line.hpp), calls the code the command builds its report
// with, and returns that report as Python objects (json_to_python.hpp).
#include <string>

#include "common/atomic_folder.hpp"
#include "common/commands.hpp"
#include "diagnose/diagnose_command.hpp"
#include "python/command_line.hpp"
#include "python/functions.hpp"
#include "python/interruptible.hpp"
#include "python/json_to_python.hpp"
#include "readers/inspect_command.hpp"
#include "records/record_dump.hpp"
#include "records/records_command.hpp"
#include "replay/replay_command.hpp"
#include "replay/replay_report_json.hpp"
#include "study/study_command.hpp"

namespace py = pybind11;

namespace aloft::host::python {

py::object diagnose(py::handle body, py::handle imu, py::handle markers, py::handle poses,
                    py::handle segments, const py::kwargs& options) {
  DiagnoseOptions o;
  CommandLine line("diagnose");
  add_diagnose_options(line.command(), o);
  std::string body_json;
  line.add_option("body", py::str(body_argument(body, &body_json)));
  line.add_option("imu", imu);
  line.add_option("markers", markers);
  line.add_option("poses", poses);
  line.add_option("segments", segments);
  line.add_options(options);
  line.parse();
  o.body_json = body_json;
  return to_python(run_interruptible([&] { return diagnose_report(o, DiagnoseOutput{}); }));
}

py::object replay(py::handle body, py::handle imu, py::handle fifo, py::handle odr_hz,
                  const py::kwargs& options) {
  ReplayOptions o;
  CommandLine line("replay");
  add_replay_options(line.command(), o);
  std::string body_json;
  line.add_option("body", py::str(body_argument(body, &body_json)));
  line.add_option("imu", imu);
  line.add_option("fifo", fifo);
  line.add_option("odr_hz", odr_hz);
  line.add_options(options);
  line.parse();
  o.body_json = body_json;
  const nlohmann::json report = run_interruptible([&] {
    const ReplayRun run = run_replay_options(o);
    return replay_report_json(run.recording, run.result);
  });
  return to_python(report);
}

py::object records(py::handle dump) {
  const std::string path = path_text(dump);
  const RecordDump read = read_record_dump(path);
  return to_python(records_json(path, read));
}

py::object study(py::handle body, py::handle imu, py::handle markers, py::handle poses, py::handle segments,
                 py::handle seed, py::handle mc_samples, py::handle threads, py::handle out,
                 const py::kwargs& options) {
  StudyOptions o;
  CommandLine line("study");
  add_study_options(line.command(), o);
  std::string body_json;
  if (!body.is_none()) line.add_option("body", py::str(body_argument(body, &body_json)));
  line.add_option("imu", imu);
  line.add_option("markers", markers);
  line.add_option("poses", poses);
  line.add_option("segments", segments);
  line.add_option("seed", seed);
  line.add_option("mc_samples", mc_samples);
  line.add_option("threads", threads);
  line.add_option("out", out);
  line.add_options(options);
  line.parse();
  o.recording.body_json = body_json;
  if (o.calibrate_to_paper) {
    throw Error(
        "study: calibrate_to_paper is the command line's (aloft study --calibrate-to-paper): it searches for "
        "minutes and reports in calibration.json, not in results.json");
  }
  check_study_options(o);
  const bool write = !out.is_none();
  const nlohmann::json results = run_interruptible([&] {
    if (write) clean_after_killed_runs(o.out_dir);
    StudyOutputs outputs = compute_study(o);
    if (write) write_study_folder(o.out_dir, outputs.files);
    return std::move(outputs.results);
  });
  return to_python(results);
}

py::object inspect(py::handle path, py::handle body, const py::kwargs& options) {
  InspectOptions o;
  CommandLine line("inspect");
  add_inspect_options(line.command(), o);
  line.add_positional(path);
  std::string body_json;
  if (!body.is_none()) line.add_option("body", py::str(body_argument(body, &body_json)));
  line.add_options(options);
  line.parse();
  o.body_json = body_json;
  return to_python(run_interruptible([&] { return inspect_summary(o); }));
}

}  // namespace aloft::host::python
