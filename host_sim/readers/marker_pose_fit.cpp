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

// The body's markers found among the file's, in the body's order.
struct MatchedMarkers {
  std::vector<std::string> names;
  std::vector<Eigen::Vector3d> body_points;
  std::vector<int> file_index;  // of each in the file's markers
};

// Throws naming every marker of the body that the file lacks.
MatchedMarkers match_markers(const MarkerTrial& markers, const Body& body) {
  const std::string& path = markers.path;
  if (body.markers_m.size() < 3) {
    throw Error(path + ": body '" + body.name + "' has " + std::to_string(body.markers_m.size()) +
                " markers; fitting poses needs at least three");
  }
  MatchedMarkers matched;
  std::vector<std::string> missing;
  for (const auto& [name, point] : body.markers_m) {
    const int index = find_marker(markers.marker_names, name);
    if (index < 0) {
      missing.push_back(name);
      continue;
    }
    matched.names.push_back(name);
    matched.body_points.push_back(point);
    matched.file_index.push_back(index);
  }
  if (!missing.empty()) {
    throw Error(path + ": marker" + (missing.size() > 1 ? "s " : " ") + join(missing) + " of body '" +
                body.name + "' not in the file (it has " + join(markers.marker_names) + ")");
  }
  return matched;
}

// The matched markers that one frame sees, kept from frame to frame so that their
// storage is reused.
struct VisibleMarkers {
  std::vector<Eigen::Vector3d> body;
  std::vector<Eigen::Vector3d> world;
  std::vector<std::size_t> marker;  // index into MatchedMarkers

  void find(const MatchedMarkers& matched, const std::vector<Eigen::Vector3d>& frame) {
    body.clear();
    world.clear();
    marker.clear();
    for (std::size_t m = 0; m < matched.file_index.size(); ++m) {
      const Eigen::Vector3d& p = frame[static_cast<std::size_t>(matched.file_index[m])];
      if (p.allFinite()) {
        body.push_back(matched.body_points[m]);
        world.push_back(p);
        marker.push_back(m);
      }
    }
  }
};

// Frame f was not posed: it extends the last gap when that ends just before it.
void add_to_gaps(std::vector<FrameRange>& gaps, std::size_t f, double time_s) {
  if (!gaps.empty() && gaps.back().last_frame + 1 == f) {
    gaps.back().last_frame = f;
    gaps.back().end_s = time_s;
  } else {
    gaps.push_back({f, f, time_s, time_s});
  }
}

// Each marker's squared residuals summed over the frames that see it, for its RMS.
struct MarkerResidualSums {
  std::vector<double> square_sum;
  std::vector<int> frames;

  explicit MarkerResidualSums(std::size_t markers) : square_sum(markers, 0.0), frames(markers, 0) {}
  void add(const std::vector<std::size_t>& seen_marker, const std::vector<double>& point_residuals) {
    for (std::size_t i = 0; i < seen_marker.size(); ++i) {
      square_sum[seen_marker[i]] += point_residuals[i] * point_residuals[i];
      ++frames[seen_marker[i]];
    }
  }
  std::vector<double> rms() const {
    std::vector<double> out;
    for (std::size_t m = 0; m < frames.size(); ++m) {
      out.push_back(frames[m] > 0 ? std::sqrt(square_sum[m] / frames[m])
                                  : std::numeric_limits<double>::quiet_NaN());
    }
    return out;
  }
};

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
  const MatchedMarkers matched = match_markers(markers, body);

  const std::size_t frames = markers.positions_m.size();
  PoseFitReport local;
  PoseFitReport& out = report ? *report : local;
  out = PoseFitReport{};
  out.rms_residual_m.assign(frames, std::numeric_limits<double>::quiet_NaN());
  out.visible_markers.assign(frames, 0);

  PoseTrial poses;
  poses.path = path;
  poses.format = markers.format;
  VisibleMarkers seen;
  std::vector<double> point_residuals;
  MarkerResidualSums marker_sums(matched.file_index.size());
  double residual_sum = 0.0;
  for (std::size_t f = 0; f < frames; ++f) {
    seen.find(matched, markers.positions_m[f]);
    out.visible_markers[f] = static_cast<int>(seen.body.size());
    Eigen::Quaterniond q;
    Eigen::Vector3d position;
    double rms = 0.0;
    const bool posed = seen.body.size() >= 3 &&
                       fit_rigid_transform(seen.body, seen.world, q, position, rms, &point_residuals);
    if (!posed) {
      add_to_gaps(out.gaps, f, markers.time_s[f]);
      continue;
    }
    if (!poses.orientation.empty() && q.dot(poses.orientation.back()) < 0.0) {
      q.coeffs() = -q.coeffs();  // same rotation, kept in the previous sample's hemisphere
    }
    poses.time_s.push_back(markers.time_s[f]);
    poses.orientation.push_back(q);
    poses.position_m.push_back(position);
    marker_sums.add(seen.marker, point_residuals);
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
  out.marker_names = matched.names;
  out.marker_rms_residual_m = marker_sums.rms();
  return poses;
}

}  // namespace aloft::host
