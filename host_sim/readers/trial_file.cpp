#include "readers/trial_file.hpp"

#include <filesystem>
#include <fstream>
#include <set>

#include "common/commands.hpp"
#include "common/file_error.hpp"
#include "readers/c3d_reader.hpp"
#include "readers/pose_reader.hpp"
#include "readers/text_cells.hpp"
#include "readers/trc_reader.hpp"

namespace aloft::host {

namespace {

// The header cells of a CSV line, trimmed and lower-cased.
std::set<std::string> header_names(const std::string& line, const std::string& path) {
  std::set<std::string> names;
  for (const auto& cell : split_csv_line(line, path, 1, 0, csv_delimiter(line)))
    names.insert(to_lower(trim(cell)));
  return names;
}

bool has_all(const std::set<std::string>& names, std::initializer_list<const char*> wanted) {
  for (const char* w : wanted) {
    if (!names.count(w)) return false;
  }
  return true;
}

const char* kind_name(TrialKind kind) {
  switch (kind) {
    case TrialKind::markers: return "marker trajectories";
    case TrialKind::poses: return "poses";
    case TrialKind::imu: return "an IMU log";
    case TrialKind::segments: return "segments";
  }
  return "unknown";
}

}  // namespace

static TrialFormat detect_trial_format_unguarded(const std::string& path) {
  const std::string extension = to_lower(std::filesystem::path(path).extension().string());
  if (extension == ".trc") return {TrialKind::markers, "trc"};
  if (extension == ".c3d") return {TrialKind::markers, "c3d"};
  if (extension == ".mot") return {TrialKind::poses, "mot"};
  if (extension == ".sto") return {TrialKind::poses, "sto"};

  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path + ": cannot open file");
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  head = without_byte_order_mark(head);
  if (head.empty()) throw Error(path + ": file is empty");
  if (head.find('\0') != std::string::npos) {
    if (head.size() >= 2 && static_cast<unsigned char>(head[1]) == 0x50) return {TrialKind::markers, "c3d"};
    throw Error(path + ": binary file that is not C3D");
  }
  // First non-blank line, and whether an OpenSim header ends somewhere in the head.
  std::string first;
  bool endheader = false;
  std::size_t start = 0;
  while (start < head.size()) {
    std::size_t end = head.find('\n', start);
    if (end == std::string::npos) end = head.size();
    const std::string line = trim(head.substr(start, end - start));
    if (first.empty()) first = line;
    if (to_lower(line) == "endheader") endheader = true;
    start = end + 1;
  }
  if (to_lower(first).rfind("pathfiletype", 0) == 0) return {TrialKind::markers, "trc"};
  if (endheader) return {TrialKind::poses, "mot"};
  const auto names = header_names(first, path);
  if (has_all(names, {"t", "qw", "qx", "qy", "qz"})) return {TrialKind::poses, "pose_csv"};
  if (has_all(names, {"segment", "start", "end"})) return {TrialKind::segments, "segments"};
  if (has_all(names, {"t", "gx", "gy", "gz"})) return {TrialKind::imu, "imu_csv"};
  if (has_all(names, {"time (s)", "gyroscope x (rad/s)"})) return {TrialKind::imu, "phyphox"};
  throw Error(path + ": cannot tell the trial format (not .trc/.c3d/.mot/.sto, and header '" +
              first.substr(0, 80) + "' is no IMU, pose or segments CSV)");
}

MarkerTrial read_marker_file(const std::string& path) {
  const TrialFormat format = detect_trial_format(path);
  if (format.name == "trc") return read_trc(path);
  if (format.name == "c3d") return read_c3d(path);
  throw Error(path + ": holds " + kind_name(format.kind) + ", not marker trajectories (.trc, .c3d)");
}

PoseTrial read_pose_file(const std::string& path, const PoseNaming& naming) {
  const TrialFormat format = detect_trial_format(path);
  if (format.name == "mot" || format.name == "sto") return read_mot(path, naming);
  if (format.name == "pose_csv") {
    if (!naming.empty())
      throw Error(path +
                  ": a pose CSV names its own columns; --pose-columns, --osim and --joint are for .mot/.sto");
    return read_pose_csv(path);
  }
  throw Error(path + ": holds " + kind_name(format.kind) + ", not poses (.mot, .sto, pose CSV)");
}

TrialFormat detect_trial_format(const std::string& path) {
  return with_file_context(path, [&] { return detect_trial_format_unguarded(path); });
}

}  // namespace aloft::host
