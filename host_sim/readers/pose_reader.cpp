#include "readers/pose_reader.hpp"

#include <array>
#include <cmath>
#include <filesystem>
#include <optional>

#include "common/commands.hpp"
#include "common/file_error.hpp"
#include "readers/free_joint.hpp"
#include "readers/text_cells.hpp"
#include "readers/time_stamps.hpp"

namespace aloft::host {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The column names for a message, the first dozen.
std::string column_list(const std::vector<std::string>& names) {
  constexpr std::size_t kShown = 12;
  std::string list;
  for (std::size_t i = 0; i < names.size() && i < kShown; ++i) list += (i ? " " : "") + names[i];
  if (names.size() > kShown) list += " ... (" + std::to_string(names.size()) + " columns)";
  return list;
}

void make_hemispheres_continuous(std::vector<Eigen::Quaterniond>& q) {
  for (std::size_t i = 1; i < q.size(); ++i) {
    if (q[i].dot(q[i - 1]) < 0.0) q[i].coeffs() = -q[i].coeffs();
  }
}

// A count from the header, checked before it is converted: more rows or columns than a
// billion is no count a file can hold.
std::optional<std::size_t> header_count(const std::string& value) {
  constexpr double kMostCount = 1e9;
  double v = 0.0;
  if (!try_parse_number(trim(value), v) || !(v >= 0.0 && v <= kMostCount) || v != std::floor(v)) {
    return std::nullopt;
  }
  return static_cast<std::size_t>(v);
}

// Column index of each rotation and translation of the joint; throws naming the missing.
struct JointColumnIndices {
  std::array<int, 3> rotation{{-1, -1, -1}};
  std::array<int, 3> translation{{-1, -1, -1}};
};

JointColumnIndices find_joint_columns(const FreeJointColumns& joint, const std::vector<std::string>& names,
                                      const std::string& path, std::size_t line) {
  JointColumnIndices out;
  auto locate = [&](const JointAxis& axis) {
    if (axis.coordinate.empty()) return -1;
    const int column = coordinate_column(names, axis.coordinate);
    if (column < 0) {
      throw Error(at_line(
          path, line,
          "no column " + axis.coordinate + " (" + joint.source + "); columns: " + column_list(names)));
    }
    return column;
  };
  for (std::size_t i = 0; i < 3; ++i) out.rotation[i] = locate(joint.rotations[i]);
  for (std::size_t i = 0; i < joint.translations.size() && i < 3; ++i)
    out.translation[i] = locate(joint.translations[i]);
  return out;
}

// What an OpenSim header declares, up to its endheader line.
struct MotHeader {
  std::optional<bool> in_degrees;
  std::optional<std::size_t> rows;
  std::optional<std::size_t> columns;
  std::size_t end_index = 0;  // of the endheader line
};

MotHeader read_mot_header(const TextFile& file, const std::string& path) {
  MotHeader header;
  std::size_t i = 0;
  for (; i < file.lines.size(); ++i) {
    const std::string line = to_lower(trim(file.lines[i]));
    if (line == "endheader") break;
    const std::size_t eq = line.find('=');
    if (eq == std::string::npos) continue;  // the name line, comments
    const std::string key = trim(line.substr(0, eq));
    const std::string value = trim(line.substr(eq + 1));
    if (key == "indegrees") {
      if (value != "yes" && value != "no") {
        throw Error(at_line(path, i + 1, "inDegrees must be yes or no, not '" + value + "'"));
      }
      header.in_degrees = value == "yes";
    } else if (key == "nrows" || key == "datarows") {
      header.rows = header_count(value);
      if (!header.rows)
        throw Error(at_line(path, i + 1, "nRows '" + value + "' is not a whole number up to 1e9"));
    } else if (key == "ncolumns" || key == "datacolumns") {
      header.columns = header_count(value);
      if (!header.columns)
        throw Error(at_line(path, i + 1, "nColumns '" + value + "' is not a whole number up to 1e9"));
    }
  }
  if (i == file.lines.size()) throw Error(path + ": no endheader line (not an OpenSim .mot/.sto)");
  header.end_index = i;
  return header;
}

// The column names, the first line after endheader that is not blank, with the time
// column among them and as many as nColumns says.
struct MotColumns {
  std::vector<std::string> names;
  std::size_t index = 0;  // of their line
  int time = -1;
  std::size_t line() const { return index + 1; }
};

MotColumns read_mot_columns(const TextFile& file, const MotHeader& header, const std::string& path) {
  MotColumns columns;
  std::size_t i = header.end_index + 1;
  while (i < file.lines.size() && is_blank(file.lines[i])) ++i;
  if (i == file.lines.size()) throw Error(path + ": no column names after endheader");
  columns.index = i;
  columns.names = split_whitespace(file.lines[i]);
  for (std::size_t k = 0; k < columns.names.size(); ++k) {
    if (to_lower(columns.names[k]) == "time") columns.time = static_cast<int>(k);
  }
  if (columns.time < 0) throw Error(at_line(path, columns.line(), "no time column"));
  if (header.columns && *header.columns != columns.names.size()) {
    throw Error(at_line(path, columns.line(),
                        std::to_string(columns.names.size()) + " column names where nColumns is " +
                            std::to_string(*header.columns)));
  }
  return columns;
}

// The free joint that the user named, or else the one recognised among the columns.
FreeJointColumns mot_free_joint(const std::optional<FreeJointColumns>& named, const MotColumns& columns,
                                const std::string& path) {
  std::vector<std::string> data_names = columns.names;
  data_names.erase(data_names.begin() + columns.time);
  const std::optional<FreeJointColumns> joint =
      named ? named : recognise_free_joint(data_names, path, columns.line());
  if (!joint) {
    throw Error(at_line(path, columns.line(),
                        "no free-joint pose among the columns (" + column_list(columns.names) + "); " +
                            how_to_name_the_pose()));
  }
  return *joint;
}

// Every row after the column names into `trial`, as a time and a pose; returns the line
// number of each row, for messages about its time stamp.
std::vector<std::size_t> read_mot_rows(const TextFile& file, const MotColumns& columns,
                                       const FreeJointColumns& joint, const JointColumnIndices& indices,
                                       double angle_scale, const std::string& path, PoseTrial& trial) {
  const std::vector<std::string>& names = columns.names;
  const bool has_position = !joint.translations.empty();
  std::vector<std::size_t> line_numbers;
  for (std::size_t i = columns.index + 1; i < file.lines.size(); ++i) {
    if (is_blank(file.lines[i])) continue;
    const std::size_t line = i + 1;
    const std::vector<std::string> cells = split_whitespace(file.lines[i]);
    if (cells.size() != names.size()) {
      throw Error(at_line(path, line,
                          std::to_string(cells.size()) + " cells where the header names " +
                              std::to_string(names.size()) + " columns (truncated or malformed row)"));
    }
    auto value = [&](int column) {
      if (column < 0) return 0.0;  // a constant axis: its value is not read
      const auto c = static_cast<std::size_t>(column);
      const double v = parse_number(cells[c], path, line, names[c]);
      if (!std::isfinite(v)) {
        throw Error(at_line(path, line, "column " + names[c] + " is not finite"));
      }
      return v;
    };
    trial.time_s.push_back(value(columns.time));
    std::array<double, 3> angles{}, distances{};
    for (std::size_t k = 0; k < 3; ++k) {
      angles[k] = value(indices.rotation[k]) * angle_scale;
      distances[k] = value(indices.translation[k]);
    }
    const Eigen::Isometry3d pose = free_joint_pose(joint, angles, distances);
    trial.orientation.emplace_back(Eigen::Matrix3d(pose.linear()));  // a rotation by construction
    if (has_position) trial.position_m.push_back(pose.translation());
    line_numbers.push_back(line);
  }
  return line_numbers;
}

}  // namespace

static PoseTrial read_mot_unguarded(const std::string& path, const PoseNaming& naming) {
  const std::optional<FreeJointColumns> named = free_joint_from_naming(naming);
  const TextFile file = read_text_file(path);
  const MotHeader header = read_mot_header(file, path);
  const MotColumns columns = read_mot_columns(file, header, path);
  // The pose first: a file that holds none is refused for that, whatever else it lacks.
  const FreeJointColumns joint = mot_free_joint(named, columns, path);
  const JointColumnIndices indices = find_joint_columns(joint, columns.names, path, columns.line());
  if (!header.in_degrees) {
    throw Error(
        at_line(path, header.end_index + 1, "header lacks inDegrees=yes|no, so angle units are unknown"));
  }
  const double angle_scale = *header.in_degrees ? kPi / 180.0 : 1.0;

  PoseTrial trial;
  trial.path = path;
  const std::string extension = to_lower(std::filesystem::path(path).extension().string());
  trial.format = extension == ".sto" ? "sto" : "mot";
  const std::vector<std::size_t> line_numbers =
      read_mot_rows(file, columns, joint, indices, angle_scale, path, trial);
  if (trial.time_s.empty()) throw Error(path + ": no rows after the column names");
  if (header.rows && *header.rows != trial.time_s.size()) {
    throw Error(path + ": holds " + std::to_string(trial.time_s.size()) + " rows where nRows is " +
                std::to_string(*header.rows) +
                (trial.time_s.size() < *header.rows ? " (truncated file?)" : ""));
  }
  check_time_stamps(trial.time_s, path, line_numbers);
  make_hemispheres_continuous(trial.orientation);
  return trial;
}

namespace {

// Columns of a pose CSV header: t, qw..qz, and x, y, z (-1 when absent).
struct PoseCsvColumns {
  int t = -1;
  int q[4] = {-1, -1, -1, -1};
  int p[3] = {-1, -1, -1};
  bool has_position() const { return p[0] >= 0; }
};

PoseCsvColumns pose_csv_columns(const std::vector<std::string>& header, const std::string& path,
                                std::size_t header_line) {
  auto find = [&](const char* name) {
    for (std::size_t k = 0; k < header.size(); ++k) {
      if (to_lower(trim(header[k])) == name) return static_cast<int>(k);
    }
    return -1;
  };
  PoseCsvColumns c;
  c.t = find("t");
  const char* quaternion[4] = {"qw", "qx", "qy", "qz"};
  const char* position[3] = {"x", "y", "z"};
  for (int k = 0; k < 4; ++k) c.q[k] = find(quaternion[k]);
  for (int k = 0; k < 3; ++k) c.p[k] = find(position[k]);
  if (c.t < 0 || c.q[0] < 0 || c.q[1] < 0 || c.q[2] < 0 || c.q[3] < 0) {
    throw Error(at_line(
        path, header_line,
        "header must hold t,qw,qx,qy,qz[,x,y,z] (qw the scalar part: scipy's as_quat() gives x, y, z, w)"));
  }
  const int positions = (c.p[0] >= 0) + (c.p[1] >= 0) + (c.p[2] >= 0);
  if (positions != 0 && positions != 3) {
    throw Error(at_line(path, header_line, "position needs all of x, y, z or none"));
  }
  return c;
}

}  // namespace

static PoseTrial read_pose_csv_unguarded(const std::string& path) {
  const TextFile file = read_text_file(path, [&](const std::string& line, std::size_t number) {
    pose_csv_columns(split_csv_line(line, path, number), path, number);
  });
  std::size_t i = 0;
  while (is_blank(file.lines[i])) ++i;
  const std::size_t header_line = i + 1;
  const std::vector<std::string> header = split_csv_line(file.lines[i], path, header_line);
  const PoseCsvColumns columns = pose_csv_columns(header, path, header_line);
  const int t = columns.t;
  const int* q = columns.q;
  const int* p = columns.p;
  const int positions = columns.has_position() ? 3 : 0;

  PoseTrial trial;
  trial.path = path;
  trial.format = "pose_csv";
  std::vector<std::size_t> line_numbers;
  for (++i; i < file.lines.size(); ++i) {
    if (is_blank(file.lines[i])) continue;
    const std::size_t line = i + 1;
    const std::vector<std::string> cells = split_csv_line(file.lines[i], path, line);
    if (cells.size() != header.size()) {
      throw Error(at_line(path, line,
                          std::to_string(cells.size()) + " cells where the header has " +
                              std::to_string(header.size()) + " (truncated or malformed row)"));
    }
    auto value = [&](int column) {
      const double v = parse_number(cells[column], path, line, header[column]);
      if (!std::isfinite(v)) {
        throw Error(at_line(path, line, "column " + header[column] + " is not finite"));
      }
      return v;
    };
    trial.time_s.push_back(value(t));
    Eigen::Quaterniond rotation(value(q[0]), value(q[1]), value(q[2]), value(q[3]));
    const double norm = rotation.norm();
    if (std::abs(norm - 1.0) > 1e-3) {
      throw Error(at_line(path, line, "quaternion norm " + std::to_string(norm) + " is not 1"));
    }
    rotation.normalize();
    trial.orientation.push_back(rotation);
    if (positions == 3) trial.position_m.emplace_back(value(p[0]), value(p[1]), value(p[2]));
    line_numbers.push_back(line);
  }
  if (trial.time_s.empty()) throw Error(path + ": no samples after the header");
  check_time_stamps(trial.time_s, path, line_numbers);
  make_hemispheres_continuous(trial.orientation);
  return trial;
}

PoseTrial read_mot(const std::string& path, const PoseNaming& naming) {
  return with_file_context(path, [&] { return read_mot_unguarded(path, naming); });
}

PoseTrial read_pose_csv(const std::string& path) {
  return with_file_context(path, [&] { return read_pose_csv_unguarded(path); });
}

}  // namespace aloft::host
