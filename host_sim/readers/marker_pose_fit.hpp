// Rigid-body poses from marker trajectories: for each frame, the rotation and
// translation that carry the body's marker set (Body::markers_m, body axes, origin at
// the centre of mass) onto the markers seen in that frame, in the least-squares sense
// (Kabsch / Umeyama without scaling, Eigen::umeyama).
//
// A frame is posed only when at least three of the body's markers are visible and those
// are not collinear; other frames are left out of the PoseTrial and reported as gaps. So
// a PoseTrial from fit_poses holds posed frames only, and a gap shows in it as a time
// step longer than the trial's usual one (body_rates.hpp skips such steps).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "common/body_file.hpp"
#include "common/trial.hpp"

namespace aloft::host {

// Frames first_frame..last_frame (0-based indices into the MarkerTrial, inclusive),
// at start_s..end_s.
struct FrameRange {
  std::size_t first_frame = 0;
  std::size_t last_frame = 0;
  double start_s = 0.0;
  double end_s = 0.0;
};

struct PoseFitReport {
  std::vector<std::size_t> posed_frames;  // MarkerTrial frame of each PoseTrial sample
  std::vector<double> rms_residual_m;     // per MarkerTrial frame; NaN where not posed
  std::vector<int> visible_markers;       // per MarkerTrial frame: the body's markers seen
  std::vector<FrameRange> gaps;           // runs of frames not posed, in order
  double max_rms_residual_m = 0.0;
  double mean_rms_residual_m = 0.0;
  // Per marker of the body (in the order of Body::markers_m): its name and its RMS distance
  // from where the fitted pose puts it, over the posed frames that show it; so a
  // misplaced or mislabelled marker can be named.
  std::vector<std::string> marker_names;
  std::vector<double> marker_rms_residual_m;
};

// Throws aloft::host::Error (one line, naming the marker file) when the body has fewer
// than three markers, when markers of the body are missing from the file (all of them
// are named), or when fewer than two frames can be posed. A body marker "M1" matches a
// file label "M1" or, failing that, one ending in ":M1" (Vicon's "Subject:M1").
PoseTrial fit_poses(const MarkerTrial& markers, const Body& body, PoseFitReport* report = nullptr);

// One frame: the pose (orientation body -> world, position of the body origin) that best
// carries body_points onto world_points (same order, at least three). Returns false, and
// leaves the outputs untouched, when the body points are collinear. point_residuals_m,
// when given, receives each point's distance from where the pose puts it.
bool fit_rigid_transform(const std::vector<Eigen::Vector3d>& body_points,
                         const std::vector<Eigen::Vector3d>& world_points, Eigen::Quaterniond& orientation,
                         Eigen::Vector3d& position, double& rms_residual_m,
                         std::vector<double>* point_residuals_m = nullptr);

}  // namespace aloft::host
