// `aloft inspect FILE [--body BODY.json]`: a JSON summary of any trial file on stdout
// (SPEC §5): {"format", "frames", "rate_hz", "duration_s", "markers", "units"} for marker
// files, the matching subset for pose and IMU files (rates of those are the median of
// their time steps), and the kept flights of a segments file. Keys beyond SPEC's say
// what a user checks before a study: occlusions, C3D layout, and with --body, how well
// the body's marker set fits each frame and where the gaps are.
#include <cmath>
#include <iostream>

#include <nlohmann/json.hpp>

#include "common/json_text.hpp"
#include "common/body_file.hpp"
#include "common/commands.hpp"
#include "readers/c3d_reader.hpp"
#include "readers/accel_at_rest.hpp"
#include "readers/imu_csv_reader.hpp"
#include "readers/imu_units.hpp"
#include "readers/inspect_command.hpp"
#include "readers/marker_pose_fit.hpp"
#include "readers/pose_naming_options.hpp"
#include "readers/pose_reader.hpp"
#include "readers/segments.hpp"
#include "readers/time_stamps.hpp"
#include "readers/trc_reader.hpp"
#include "readers/trial_file.hpp"

namespace aloft::host {

namespace {

using Json = nlohmann::ordered_json;

double duration_of(const std::vector<double>& time_s) {
  return time_s.size() < 2 ? 0.0 : time_s.back() - time_s.front();
}

Json summarise_markers(const std::string& path, const TrialFormat& format, const std::string& body_path,
                       const std::string& body_json) {
  C3dDetails details;
  const MarkerTrial trial = format.name == "c3d" ? read_c3d(path, &details) : read_trc(path);
  Json out;
  out["format"] = trial.format;
  out["frames"] = trial.time_s.size();
  out["rate_hz"] = trial.rate_hz;
  out["duration_s"] = duration_of(trial.time_s);
  out["markers"] = trial.marker_names;
  out["units"] = trial.units_in_file;
  out["start_s"] = trial.time_s.front();
  std::size_t occluded = 0;
  std::size_t frames_below_three = 0;
  for (const auto& frame : trial.positions_m) {
    std::size_t visible = 0;
    for (const auto& p : frame) visible += p.allFinite() ? 1 : 0;
    occluded += frame.size() - visible;
    frames_below_three += visible < 3 ? 1 : 0;
  }
  out["occluded_samples"] = occluded;
  out["frames_with_fewer_than_3_markers"] = frames_below_three;
  if (format.name == "c3d") {
    out["c3d"] = {{"processor", details.processor},
                  {"data", details.float_data ? "float" : "integer"},
                  {"point_scale", details.point_scale},
                  {"first_frame", details.first_frame},
                  {"analog_samples_per_frame", details.analog_samples_per_frame},
                  {"parameter_damage", details.parameter_damage},
                  {"parameter_repairs", details.parameter_repairs}};
  }
  if (!body_path.empty()) {
    const Body body = read_body(body_path, body_json);
    PoseFitReport report;
    const PoseTrial poses = fit_poses(trial, body, &report);
    Json gaps = Json::array();
    for (const FrameRange& g : report.gaps) {
      gaps.push_back({{"first_frame", g.first_frame},
                      {"last_frame", g.last_frame},
                      {"start_s", g.start_s},
                      {"end_s", g.end_s}});
    }
    out["pose_fit"] = {{"body", body.name},
                       {"posed_frames", poses.time_s.size()},
                       {"gaps", gaps},
                       {"mean_rms_residual_m", report.mean_rms_residual_m},
                       {"max_rms_residual_m", report.max_rms_residual_m}};
  }
  return out;
}

Json summarise_poses(const std::string& path, const PoseNaming& naming) {
  const PoseTrial trial = read_pose_file(path, naming);
  Json out;
  out["format"] = trial.format;
  out["frames"] = trial.time_s.size();
  out["rate_hz"] = estimated_rate_hz(trial.time_s);
  out["duration_s"] = duration_of(trial.time_s);
  out["start_s"] = trial.time_s.front();
  out["has_position"] = !trial.position_m.empty();
  if (trial.format == "pose_csv") {
    // The mistake a pose CSV invites: scipy writes its quaternions scalar last.
    out["quaternion_order"] =
        "qw, qx, qy, qz by column name, qw the scalar part; scipy's Rotation.as_quat() gives x, y, z, w";
  }
  return out;
}

// What the physics says of the log's units, where the log alone can tell.
Json unit_notes(const ImuLog& log) {
  Json notes = Json::array();
  const double rest = accel_at_rest(log);
  if (rest > 0.85 && rest < 1.15) {
    notes.push_back(
        "the accelerometer reads about 1 at rest where gravity reads 9.81 m/s^2: it is in g "
        "(--accel-units g)");
  }
  notes.push_back(
      "rates and times are checked against Euler's equations for the body by aloft diagnose "
      "(a gyro in deg/s or times in ms are named there)");
  return notes;
}

// The quantities the log holds, by the plain layout's column names (SPEC §3).
Json imu_columns_read(const ImuLog& log) {
  Json columns = {"t", "gx", "gy", "gz"};
  if (!log.accel_m_s2.empty()) {
    for (const char* name : {"ax", "ay", "az"}) columns.push_back(name);
  }
  if (!log.rotor_rad_s.empty()) columns.push_back("rotor_rad_s");
  return columns;
}

Json summarise_imu(const std::string& path, const ImuUnits& units) {
  ImuLog log = read_imu_csv(path);
  convert_to_si(log, units);
  Json out;
  out["format"] = log.format;
  out["frames"] = log.time_s.size();
  out["rate_hz"] = estimated_rate_hz(log.time_s);
  out["duration_s"] = duration_of(log.time_s);
  out["units"] = "rad/s";
  out["start_s"] = log.time_s.front();
  out["columns"] = imu_columns_read(log);
  out["has_accelerometer"] = !log.accel_m_s2.empty();
  out["has_rotor_speed"] = !log.rotor_rad_s.empty();
  double peak = 0.0;
  for (const auto& w : log.gyro_rad_s) peak = std::max(peak, w.norm());
  out["max_gyro_rad_s"] = peak;
  if (!log.accel_m_s2.empty()) out["accel_at_rest_m_s2"] = accel_at_rest(log);
  if (!log.rotor_rad_s.empty()) {
    double rotor_peak = 0.0;
    for (const double w : log.rotor_rad_s) rotor_peak = std::max(rotor_peak, std::abs(w));
    out["max_abs_rotor_rad_s"] = rotor_peak;
  }
  Json notes = unit_notes(log);
  if (!log.rotor_rad_s.empty()) {
    notes.push_back(
        "rotor_rad_s is the speed of the body file's rotor (rad/s, whatever --gyro-units says); "
        "aloft replay refuses this log with a body file that has no rotor");
  }
  out["notes"] = notes;
  return out;
}

Json summarise_segments(const std::string& path) {
  Json list = Json::array();
  for (const Segment& s : read_segments_csv(path)) {
    list.push_back({{"segment", s.name}, {"start_s", s.start_s}, {"end_s", s.end_s}, {"comment", s.comment}});
  }
  Json out;
  out["format"] = "segments";
  out["segments"] = list;
  return out;
}

}  // namespace

void add_inspect_options(CLI::App& command, InspectOptions& options) {
  command.add_option("file", options.file, "trial file: .trc, .c3d, .mot, .sto, pose/IMU/segments CSV")
      ->required();
  command.add_option("--body", options.body,
                     "body file: also fit its marker set to each frame of a marker file");
  add_pose_naming_options(command, options.naming);
  add_imu_unit_options(command, options.units);
}

Json inspect_summary(const InspectOptions& o) {
  const TrialFormat format = detect_trial_format(o.file);
  if (!o.body.empty() && format.kind != TrialKind::markers) {
    throw Error(o.file + ": --body applies to marker files only");
  }
  switch (format.kind) {
    case TrialKind::markers: return summarise_markers(o.file, format, o.body, o.body_json);
    case TrialKind::poses: return summarise_poses(o.file, o.naming);
    case TrialKind::imu: return summarise_imu(o.file, o.units);
    case TrialKind::segments: return summarise_segments(o.file);
  }
  return Json();
}

void add_inspect_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("inspect", "summarise a trial file (markers, poses, IMU log, segments) as JSON");
  auto options = std::make_shared<InspectOptions>();
  add_inspect_options(*cmd, *options);
  cmd->callback([options] { std::cout << json_text(inspect_summary(*options)) << '\n'; });
}

}  // namespace aloft::host
