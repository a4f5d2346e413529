// `aloft diagnose` (SPEC §4): reads the body and one kind of trial, diagnoses the gap
// between the nominal torque-free model and the measured motion, prints a short summary
// and writes the JSON report (--json) and the plots (--plot) only when all went well.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <thread>

#include "common/json_text.hpp"
#include "common/atomic_file.hpp"
#include "common/body_file.hpp"
#include "common/commands.hpp"
#include "common/option_checks.hpp"
#include "diagnose/1_input/airborne_windows.hpp"
#include "diagnose/1_input/flight_input.hpp"
#include "diagnose/1_input/marker_fit_check.hpp"
#include "diagnose/1_input/segment_checks.hpp"
#include "diagnose/5_flow/diagnosis.hpp"
#include "diagnose/diagnose_command.hpp"
#include "diagnose/6_report/corrected_body.hpp"
#include "diagnose/6_report/gap_plot.hpp"
#include "diagnose/6_report/report_json.hpp"
#include "diagnose/6_report/report_text.hpp"
#include "diagnose/terminal_progress.hpp"
#include "readers/accel_at_rest.hpp"
#include "readers/imu_csv_reader.hpp"
#include "readers/imu_units.hpp"
#include "readers/marker_pose_fit.hpp"
#include "readers/pose_naming_options.hpp"
#include "readers/rate_units_check.hpp"
#include "readers/segments.hpp"
#include "readers/time_stamps.hpp"
#include "readers/trial_file.hpp"

namespace aloft::host {
namespace {

// "A:B" in seconds, A < B.
std::pair<double, double> parse_window(const std::string& text) {
  const auto colon = text.find(':');
  const std::string bad = "--window " + text + ": expected A:B with start A < end B in seconds";
  if (colon == std::string::npos) throw Error(bad);
  try {
    std::size_t used_a = 0, used_b = 0;
    const std::string a_text = text.substr(0, colon), b_text = text.substr(colon + 1);
    const double a = std::stod(a_text, &used_a);
    const double b = std::stod(b_text, &used_b);
    if (used_a != a_text.size() || used_b != b_text.size() || !std::isfinite(a) || !std::isfinite(b) ||
        !(a < b)) {
      throw Error(bad);
    }
    return {a, b};
  } catch (const std::logic_error&) {
    throw Error(bad);
  }
}

double log_duration(const ImuLog& log) {
  return log.time_s.size() > 1 ? log.time_s.back() - log.time_s.front() : 0.0;
}

// --threads, or every core (capped as the option is) when it is not given.
int session_threads(int asked) {
  if (asked > 0) return asked;
  return static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 64u));
}

std::string file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

void require_enough_samples(const diagnose::Flight& flight, const std::string& source) {
  if (flight.size() < diagnose::kMinimumSamples) {
    throw Error(source + ": only " + std::to_string(flight.size()) + " samples in the flight; at least " +
                std::to_string(diagnose::kMinimumSamples) + " are needed to judge it");
  }
}

// What the options name: the flights, whether they are a session, and the source for
// messages.
struct Trial {
  std::vector<diagnose::Flight> flights;
  bool session = false;
  bool found_by_detector = false;  // a long log split by the accelerometer's detector
  std::string source;
};

// The flights' rates as the unit check reads them (readers/rate_units_check.hpp), which
// study shares without knowing diagnose's flights.
std::vector<RateSeries> rate_series(const std::vector<diagnose::Flight>& flights) {
  std::vector<RateSeries> out;
  out.reserve(flights.size());
  for (const diagnose::Flight& f : flights) out.push_back({f.sensor_to_body, f.time_s, f.omega, f.usable});
  return out;
}

// The log in SI units, its accelerometer checked (a log in g would be one long flight).
ImuLog read_imu_log(const DiagnoseOptions& o) {
  ImuLog log = read_imu_csv(o.imu);
  convert_to_si(log, o.imu_units);
  check_accel_units(log);
  return log;
}

// A word on a sample rate no gyro logs at, which times in ms give (500 Hz reads 0.5 Hz).
std::string sample_rate_hint(const ImuLog& log) {
  const double rate = estimated_rate_hz(log.time_s);
  if (!(rate > 0.0) || rate >= 10.0) return "";
  char text[112];
  std::snprintf(text, sizeof text, " (%.3g samples per second: are its times in ms? --time-units ms)", rate);
  return text;
}

Trial read_trial(const DiagnoseOptions& o, const Body& body) {
  Trial t;
  if (!o.imu.empty()) {
    t.source = o.imu;
    const ImuLog log = read_imu_log(o);
    if (!o.segments.empty()) {
      t.session = true;
      const std::vector<Segment> segments = read_segments_csv(o.segments);
      diagnose::check_segments(log, segments, o.segments);
      t.flights = diagnose::flights_from_given_segments(log, body, o.body, segments);
    } else if (!o.window.empty()) {
      const auto [a, b] = parse_window(o.window);
      diagnose::check_segments(log, {{o.window, a, b, ""}}, "--window");
      t.flights = diagnose::flights_from_given_segments(log, body, o.body,
                                                        {{file_name(o.imu) + " " + o.window, a, b, ""}});
      t.source = o.imu + " (window " + o.window + ")";
    } else if (log_duration(log) > diagnose::kLongLog_s) {
      // A long log holds rest or several throws: never diagnose it as one flight.
      char length[32];
      std::snprintf(length, sizeof length, "%.1f s", log_duration(log));
      if (log.accel_m_s2.empty()) {
        throw Error(o.imu + ": a " + length + " log without an accelerometer to find its flights by" +
                    sample_rate_hint(log) + "; give --segments or --window");
      }
      const std::vector<Segment> windows = diagnose::airborne_windows(log, body, o.body);
      if (windows.empty()) {
        throw Error(o.imu + ": the firmware's release and landing code finds no flight in this " + length +
                    " log; give --segments or --window");
      }
      t.session = true;
      t.found_by_detector = true;
      t.flights = diagnose::flights_from_segments(log, body, windows);
    } else {
      t.flights.push_back(diagnose::flight_from_imu(log, body, -INFINITY, INFINITY, file_name(o.imu)));
    }
    check_rate_units(rate_series(t.flights), body, o.imu);
  } else if (!o.markers.empty()) {
    t.source = o.markers;
    PoseFitReport fit_report;
    const MarkerTrial trial = read_marker_file(o.markers);
    const PoseTrial poses = fit_poses(trial, body, &fit_report);
    if (const auto misfit = diagnose::marker_misfit(trial, body, fit_report))
      throw Error(o.markers + ": " + *misfit);
    t.flights.push_back(diagnose::flight_from_poses(poses, file_name(o.markers)));
  } else {
    t.source = o.poses;
    t.flights.push_back(
        diagnose::flight_from_poses(read_pose_file(o.poses, o.pose_naming), file_name(o.poses)));
  }
  return t;
}

}  // namespace

nlohmann::json diagnose_report(const DiagnoseOptions& o, const DiagnoseOutput& output) {
  const int inputs = !o.imu.empty() + !o.markers.empty() + !o.poses.empty();
  if (inputs != 1) throw Error("diagnose: give exactly one of --imu, --markers, --poses");
  if ((!o.segments.empty() || !o.window.empty()) && o.imu.empty()) {
    throw Error("diagnose: --segments and --window apply to --imu only");
  }
  if (!o.segments.empty() && !o.window.empty()) {
    throw Error("diagnose: give --segments or --window, not both");
  }
  const Body body = read_body(o.body, o.body_json);
  const diagnose::NominalInertia nominal = diagnose::NominalInertia::of(body.inertia);

  Trial trial = read_trial(o, body);
  std::vector<diagnose::Flight>& flights = trial.flights;  // the diagnosis sets each one's gyro filter
  const bool session = trial.session;
  const bool found_by_detector = trial.found_by_detector;
  const std::string& source = trial.source;
  std::ostringstream unused;
  std::ostream& summary = output.summary ? *output.summary : unused;

  nlohmann::json report;
  if (session) {
    diagnose::SessionDiagnosis d = diagnose::diagnose_session(
        flights, nominal, session_threads(o.threads),
        output.terminal_progress ? diagnose::terminal_flight_progress() : ParallelProgress{});
    if (output.terminal_progress) diagnose::clear_terminal_progress();
    if (found_by_detector) {
      d.pooled.notes.push_back(
          std::to_string(flights.size()) +
          " flight(s) found by the firmware's release and landing code (no --segments or --window given)");
    }
    report = diagnose::session_report(d);
    summary << diagnose::session_summary(d);
    if (!o.plot.empty()) diagnose::write_session_plots(d, nominal, o.plot);
  } else {
    require_enough_samples(flights.front(), source);
    const diagnose::FlightDiagnosis d = diagnose::diagnose_flight(flights.front(), nominal);
    report = diagnose::flight_report(d);
    summary << diagnose::flight_summary(d);
    if (!o.plot.empty()) diagnose::write_flight_plots(d, nominal, o.plot);
  }
  // The same words as `aloft study`'s note on its nominal figure (docs/study.md,
  // "Study and diagnose on the same data"): the two commands answer different questions.
  const char* const measures =
      "nominal model from the initial rate fitted to the whole flight (its best case); "
      "aloft study seeds a simulation from each measured sample instead, which drifts further";
  report["baseline"]["measures"] = measures;
  summary << "  baseline measures: " << measures << "\n";
  if (!o.json.empty()) {
    write_file_atomically(o.json, [&](std::ostream& out) { out << json_text(report) << "\n"; });
  }
  if (!o.corrected_body.empty()) {
    const bool written =
        o.body_json.empty() ? diagnose::write_corrected_body(o.body, report, o.corrected_body)
                            : diagnose::write_corrected_body_from_text(o.body_json, report, o.corrected_body);
    summary << "  corrected body: "
            << (written ? o.corrected_body + " (the body file with the fitted tensor)"
                        : "none written (the verdict changes no moment and no axis)")
            << "\n";
  }
  return report;
}

void add_diagnose_options(CLI::App& command, DiagnoseOptions& options) {
  CLI::App* cmd = &command;
  cmd->add_option("--body", options.body, "body file (JSON: docs/file-formats.md)")->required();
  cmd->add_option("--imu", options.imu, "IMU log, plain or phyphox CSV");
  cmd->add_option("--segments", options.segments, "segments CSV: one flight per row (pooled analysis)");
  cmd->add_option("--window", options.window, "A:B, the flight inside the IMU log (seconds)");
  add_imu_unit_options(*cmd, options.imu_units);
  cmd->add_option("--markers", options.markers, "marker trajectories (.trc or .c3d)");
  cmd->add_option("--poses", options.poses, "poses (.mot, .sto or pose CSV)");
  add_pose_naming_options(*cmd, options.pose_naming);
  cmd->add_option("--json", options.json, "write the JSON report here")->check(output_file());
  cmd->add_option("--corrected-body", options.corrected_body,
                  "write the body file with the fitted tensor here, when the verdict fits one")
      ->check(output_file());
  cmd->add_option("--plot", options.plot, "write DA, relative error and invariant plots (SVG, PNG) here")
      ->check(output_folder());
  // No CLI::Range: its description shows in the help as "INT:INT in [1 - 64]".
  cmd->add_option("--threads", options.threads, "threads for a session, 1 to 64 (default: every core)")
      ->type_name("N")
      ->check(CLI::Range(1, 64).description(""));
}

void add_diagnose_command(CLI::App& app) {
  auto options = std::make_shared<DiagnoseOptions>();
  auto* cmd =
      app.add_subcommand("diagnose",
                         "where the simulation parts from the measured motion, which unmodelled effect "
                         "causes it, and how far the gap shrinks with it (judged on held-out data)");
  add_diagnose_options(*cmd, *options);
  cmd->callback([options] { (void)diagnose_report(*options, {&std::cout, true}); });
}

}  // namespace aloft::host
