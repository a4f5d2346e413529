#include "study/recorded_flights.hpp"

#include <cmath>
#include <filesystem>

#include "common/commands.hpp"
#include "readers/imu_csv_reader.hpp"
#include "readers/marker_pose_fit.hpp"
#include "readers/rate_units_check.hpp"
#include "readers/segments.hpp"
#include "readers/time_stamps.hpp"
#include "readers/trial_file.hpp"
#include "study/paper_cylinder.hpp"
#include "study/tangent_spline_resampler.hpp"

namespace aloft::host {
namespace {

std::string stem_of(const std::string& path) { return std::filesystem::path(path).stem().string(); }

// A log's rates and times are checked from the physics as `aloft diagnose` checks them
// (readers/rate_units_check.hpp), so that a gyro in °/s or times in ms are refused
// with the option that converts them rather than simulated into non-finite figures. The
// rates are already in body axes here.
RateSeries unit_check_flight(const std::vector<double>& time_s,
                             const std::vector<Eigen::Vector3d>& body_rate) {
  RateSeries f;
  f.time_s = time_s;
  f.omega = body_rate;
  f.usable.assign(time_s.size(), 1);
  return f;
}

StudyFlight pose_flight_from(const PoseTrial& poses, const std::string& path, nlohmann::json& description) {
  if (poses.time_s.size() < 3) {
    throw Error(path + ": " + std::to_string(poses.time_s.size()) +
                " usable poses; the study needs at least 3");
  }
  description["poses"] = poses.time_s.size();
  description["gaps"] = time_gaps(poses.time_s);
  description["resampling"] = "C1 cubic Hermite spline in the tangent space of SO(3), to 1000 Hz";
  const ResampledPoses resampled = resample_poses(poses.time_s, poses.orientation, paper::kResampleRateHz);
  StudyFlight f = make_pose_flight(stem_of(path), resampled);
  description["samples"] = f.samples();
  return f;
}

// The one flight of a marker file, from the poses fitted to the body's markers.
StudyFlight marker_flight(const RecordingInput& in, const Body& body, nlohmann::json& d) {
  // The readers' one dispatch on the file type (readers/trial_file.hpp).
  const MarkerTrial markers = read_marker_file(in.markers_path);
  if (body.markers_m.size() < 3) {
    throw Error(in.body_path + ": the body needs at least 3 \"markers\" to fit " + in.markers_path);
  }
  d["kind"] = "markers";
  d["markers"] = in.markers_path;
  d["marker_frames"] = markers.time_s.size();
  PoseFitReport report;
  const PoseTrial poses = fit_poses(markers, body, &report);
  nlohmann::json unposed = nlohmann::json::array();
  for (const FrameRange& g : report.gaps) {
    unposed.push_back({{"first_frame", g.first_frame},
                       {"last_frame", g.last_frame},
                       {"start_s", g.start_s},
                       {"end_s", g.end_s}});
  }
  d["unposed_frames"] = unposed;  // fewer than three markers visible: bridged by the spline
  d["mean_fit_residual_m"] = report.mean_rms_residual_m;
  d["max_fit_residual_m"] = report.max_rms_residual_m;
  return pose_flight_from(poses, in.markers_path, d);
}

// The segments of an IMU log to study: those of the segments file, or the whole log.
std::vector<Segment> imu_segments(const RecordingInput& in, const ImuLog& log, nlohmann::json& d) {
  std::vector<Segment> segments;
  if (!in.segments_path.empty()) {
    segments = read_segments_csv(in.segments_path);
    d["segments"] = in.segments_path;
  } else {
    segments.push_back({"whole log", log.time_s.front(), log.time_s.back(), ""});
  }
  return segments;
}

// One flight per segment of an IMU log, its gyro rotated into body axes; the rates and
// times are checked against the physics once every segment is read.
std::vector<StudyFlight> imu_flights(const RecordingInput& in, const Body& body, nlohmann::json& d) {
  ImuLog log = read_imu_csv(in.imu_path);
  convert_to_si(log, in.imu_units);
  d["kind"] = "imu";
  d["imu"] = in.imu_path;
  d["compared"] = "gyro rotated into body axes, at the log's own samples; body rates simulated";
  const Eigen::Matrix3d to_body = body.imu_to_body.normalized().toRotationMatrix();
  const std::vector<Segment> segments = imu_segments(in, log, d);
  std::vector<StudyFlight> out;
  nlohmann::json flights = nlohmann::json::array();
  std::vector<RateSeries> unit_checked;
  for (const Segment& s : segments) {
    std::vector<double> t;
    std::vector<Eigen::Vector3d> w;
    for (std::size_t i = 0; i < log.time_s.size(); ++i) {
      if (log.time_s[i] >= s.start_s && log.time_s[i] <= s.end_s) {
        t.push_back(log.time_s[i]);
        w.push_back(to_body * log.gyro_rad_s[i]);
      }
    }
    unit_checked.push_back(unit_check_flight(t, w));
    const std::string name =
        segments.size() > 1 || !in.segments_path.empty() ? "segment " + s.name : stem_of(in.imu_path);
    if (t.size() < 3) {
      throw Error((in.segments_path.empty() ? in.imu_path : in.segments_path) + ": " + name + " (" +
                  std::to_string(s.start_s) + " to " + std::to_string(s.end_s) + " s) holds " +
                  std::to_string(t.size()) + " gyro samples of " + in.imu_path + "; at least 3 are needed");
    }
    StudyFlight f = make_rate_flight(name, t, w);
    f.start_s = s.start_s;
    f.end_s = s.end_s;
    flights.push_back({{"flight", name},
                       {"start_s", s.start_s},
                       {"end_s", s.end_s},
                       {"samples", t.size()},
                       {"comment", s.comment},
                       {"gaps", time_gaps(t)}});
    out.push_back(std::move(f));
  }
  check_rate_units(unit_checked, body, in.imu_path);
  d["flights"] = flights;
  return out;
}

}  // namespace

nlohmann::json time_gaps(const std::vector<double>& time_s) {
  nlohmann::json gaps = nlohmann::json::array();
  const double step = median_time_step(time_s);
  if (!(step > 0.0)) return gaps;
  const std::vector<char> gap_after = steps_followed_by_gap(time_s);
  for (std::size_t i = 1; i < time_s.size(); ++i) {
    if (gap_after[i - 1]) {
      const double dt = time_s[i] - time_s[i - 1];
      gaps.push_back({{"start_s", time_s[i - 1]},
                      {"end_s", time_s[i]},
                      {"missing_samples", std::lround(dt / step) - 1}});
    }
  }
  return gaps;
}

RecordedTrial load_recorded_trial(const RecordingInput& in) {
  RecordedTrial out;
  out.body = read_body(in.body_path, in.body_json);
  nlohmann::json& d = out.description;
  d["body"] = in.body_path;

  if (!in.markers_path.empty()) {
    out.flights.push_back(marker_flight(in, out.body, d));
  } else if (!in.poses_path.empty()) {
    const PoseTrial poses = read_pose_file(in.poses_path, in.pose_naming);
    d["kind"] = "poses";
    d["poses_file"] = in.poses_path;
    out.flights.push_back(pose_flight_from(poses, in.poses_path, d));
  } else {
    out.flights = imu_flights(in, out.body, d);
  }
  return out;
}

}  // namespace aloft::host
