#include "readers/marker_pose_fit.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <cmath>
#include <limits>
#include <sstream>

#include "common/commands.hpp"

namespace aloft::host {

namespace {

// Relative size of the second singular value of the centred body points below which
// they count as collinear: the rotation about their line is then undetermined.
constexpr double kCollinearRatio = 1e-6;

int find_marker(const std::vector<std::string>& labels, const std::string& name) {
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] == name) return static_cast<int>(i);
  }
  const std::string suffix = ":" + name;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const std::string& l = labels[i];
    if (l.size() > suffix.size() && l.compare(l.size() - suffix.size(), suffix.size(), suffix) == 0) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

bool fit_rigid_transform(const std::vector<Eigen::Vector3d>& body_points,
                         const std::vector<Eigen::Vector3d>& world_points, Eigen::Quaterniond& orientation,
                         Eigen::Vector3d& position, double& rms_residual_m,
                         std::vector<double>* point_residuals_m) {
  const auto n = static_cast<Eigen::Index>(body_points.size());
  if (n < 3 || world_points.size() != body_points.size()) return false;
  Eigen::Matrix3Xd body(3, n);
  Eigen::Matrix3Xd world(3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    body.col(i) = body_points[static_cast<std::size_t>(i)];
    world.col(i) = world_points[static_cast<std::size_t>(i)];
  }
  const Eigen::Matrix3Xd centred = body.colwise() - body.rowwise().mean();
  const Eigen::JacobiSVD<Eigen::Matrix3Xd> spread(centred);
  const Eigen::Vector3d s = spread.singularValues();
  if (!(s(1) > kCollinearRatio * s(0))) return false;

  const Eigen::Matrix4d transform = Eigen::umeyama(body, world, false);
  const Eigen::Matrix3d rotation = transform.topLeftCorner<3, 3>();
  const Eigen::Vector3d translation = transform.topRightCorner<3, 1>();
  const Eigen::Matrix3Xd residual = (rotation * body).colwise() + translation - world;
  orientation = Eigen::Quaterniond(rotation).normalized();
  position = translation;
  rms_residual_m = std::sqrt(residual.squaredNorm() / static_cast<double>(n));
  if (point_residuals_m) {
    point_residuals_m->resize(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i)
      (*point_residuals_m)[static_cast<std::size_t>(i)] = residual.col(i).norm();
  }
  return true;
}

PoseTrial fit_poses(const MarkerTrial& markers, const Body& body, PoseFitReport* report) {
  const std::string& path = markers.path;
  if (body.markers_m.size() < 3) {
    throw Error(path + ": body '" + body.name + "' has " + std::to_string(body.markers_m.size()) +
                " markers; fitting poses needs at least three");
  }
  std::vector<std::string> body_names;
  std::vector<Eigen::Vector3d> body_points;
  std::vector<int> file_index;
  std::vector<std::string> missing;
  for (const auto& [name, point] : body.markers_m) {
    const int index = find_marker(markers.marker_names, name);
    if (index < 0) {
      missing.push_back(name);
      continue;
    }
    body_names.push_back(name);
    body_points.push_back(point);
    file_index.push_back(index);
  }
  if (!missing.empty()) {
    throw Error(path + ": marker" + (missing.size() > 1 ? "s " : " ") + join(missing) + " of body '" +
                body.name + "' not in the file (it has " + join(markers.marker_names) + ")");
  }

  const std::size_t frames = markers.positions_m.size();
  PoseFitReport local;
  PoseFitReport& out = report ? *report : local;
  out = PoseFitReport{};
  out.rms_residual_m.assign(frames, std::numeric_limits<double>::quiet_NaN());
  out.visible_markers.assign(frames, 0);

  PoseTrial poses;
  poses.path = path;
  poses.format = markers.format;
  std::vector<Eigen::Vector3d> seen_body;
  std::vector<Eigen::Vector3d> seen_world;
  std::vector<std::size_t> seen_marker;
  std::vector<double> point_residuals;
  std::vector<double> marker_square_sum(file_index.size(), 0.0);
  std::vector<int> marker_frames(file_index.size(), 0);
  double residual_sum = 0.0;
  for (std::size_t f = 0; f < frames; ++f) {
    seen_body.clear();
    seen_world.clear();
    seen_marker.clear();
    for (std::size_t m = 0; m < file_index.size(); ++m) {
      const Eigen::Vector3d& p = markers.positions_m[f][static_cast<std::size_t>(file_index[m])];
      if (p.allFinite()) {
        seen_body.push_back(body_points[m]);
        seen_world.push_back(p);
        seen_marker.push_back(m);
      }
    }
    out.visible_markers[f] = static_cast<int>(seen_body.size());
    Eigen::Quaterniond q;
    Eigen::Vector3d position;
    double rms = 0.0;
    const bool posed = seen_body.size() >= 3 &&
                       fit_rigid_transform(seen_body, seen_world, q, position, rms, &point_residuals);
    if (!posed) {
      if (!out.gaps.empty() && out.gaps.back().last_frame + 1 == f) {
        out.gaps.back().last_frame = f;
        out.gaps.back().end_s = markers.time_s[f];
      } else {
        out.gaps.push_back({f, f, markers.time_s[f], markers.time_s[f]});
      }
      continue;
    }
    if (!poses.orientation.empty() && q.dot(poses.orientation.back()) < 0.0) {
      q.coeffs() = -q.coeffs();  // same rotation, kept in the previous sample's hemisphere
    }
    poses.time_s.push_back(markers.time_s[f]);
    poses.orientation.push_back(q);
    poses.position_m.push_back(position);
    for (std::size_t i = 0; i < seen_marker.size(); ++i) {
      marker_square_sum[seen_marker[i]] += point_residuals[i] * point_residuals[i];
      ++marker_frames[seen_marker[i]];
    }
    out.posed_frames.push_back(f);
    out.rms_residual_m[f] = rms;
    out.max_rms_residual_m = std::max(out.max_rms_residual_m, rms);
    residual_sum += rms;
  }
  if (poses.time_s.size() < 2) {
    throw Error(path + ": only " + std::to_string(poses.time_s.size()) + " of " + std::to_string(frames) +
                " frames show three non-collinear markers of body '" + body.name + "'; no flight to analyse");
  }
  out.mean_rms_residual_m = residual_sum / static_cast<double>(poses.time_s.size());
  out.marker_names = body_names;
  for (std::size_t m = 0; m < file_index.size(); ++m) {
    out.marker_rms_residual_m.push_back(marker_frames[m] > 0
                                            ? std::sqrt(marker_square_sum[m] / marker_frames[m])
                                            : std::numeric_limits<double>::quiet_NaN());
  }
  return poses;
}

}  // namespace aloft::host
