#include "readers/pose_reader.hpp"

#include <array>
#include <cmath>
#include <filesystem>
#include <optional>

#include "common/commands.hpp"
#include "readers/text_cells.hpp"
#include "readers/time_stamps.hpp"

namespace aloft::host {

namespace {

constexpr double kPi = 3.14159265358979323846;

void make_hemispheres_continuous(std::vector<Eigen::Quaterniond>& q) {
  for (std::size_t i = 1; i < q.size(); ++i) {
    if (q[i].dot(q[i - 1]) < 0.0) q[i].coeffs() = -q[i].coeffs();
  }
}

// Free-joint slot of a .mot column: 0..2 rotations about x, y, z; 3..5 translations
// along x, y, z; nullopt when the name says neither.
std::optional<int> free_joint_slot(const std::string& column) {
  const std::string name = to_lower(column);
  const std::string coord = "coord_";
  const std::size_t at = name.rfind(coord);
  if (at != std::string::npos && at + coord.size() + 1 == name.size()) {
    const char digit = name.back();
    if (digit >= '0' && digit <= '5') return digit - '0';
  }
  const std::size_t underscore = name.rfind('_');
  const std::string suffix = underscore == std::string::npos ? name : name.substr(underscore + 1);
  const char* axes = "xyz";
  for (int a = 0; a < 3; ++a) {
    const std::string x(1, axes[a]);
    if (suffix == "r" + x || suffix == "rot" + x || suffix == "rotation" + x) return a;
    if (suffix == "t" + x || suffix == "trans" + x || suffix == "translation" + x) return 3 + a;
  }
  return std::nullopt;
}

// Column index per free-joint slot (-1: absent), or throws.
std::array<int, 6> free_joint_columns(const std::vector<std::string>& names, int time_column,
                                      const std::string& path, std::size_t line) {
  std::array<int, 6> slot_column;
  slot_column.fill(-1);
  bool any_recognised = false;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (static_cast<int>(i) == time_column) continue;
    const auto slot = free_joint_slot(names[i]);
    if (!slot) continue;
    any_recognised = true;
    if (slot_column[*slot] >= 0) {
      throw Error(at_line(path, line, "columns " + names[slot_column[*slot]] + " and " + names[i] +
                                          " name the same free-joint coordinate"));
    }
    slot_column[*slot] = static_cast<int>(i);
  }
  const std::size_t others = names.size() - 1;
  if (!any_recognised && (others == 3 || others == 6)) {
    int slot = 0;
    for (std::size_t i = 0; i < names.size(); ++i) {
      if (static_cast<int>(i) != time_column) slot_column[slot++] = static_cast<int>(i);
    }
    return slot_column;
  }
  if (slot_column[0] < 0 || slot_column[1] < 0 || slot_column[2] < 0) {
    throw Error(at_line(path, line,
                        "cannot find the three free-joint rotation columns (names ending in "
                        "rx/ry/rz, rotx/roty/rotz or _coord_0.._coord_2)"));
  }
  const int translations = (slot_column[3] >= 0) + (slot_column[4] >= 0) + (slot_column[5] >= 0);
  if (translations != 0 && translations != 3) {
    throw Error(at_line(path, line, "free-joint translations need all three columns or none"));
  }
  return slot_column;
}

Eigen::Quaterniond cardan_xyz(double a, double b, double c) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX())) *
         Eigen::Quaterniond(Eigen::AngleAxisd(b, Eigen::Vector3d::UnitY())) *
         Eigen::Quaterniond(Eigen::AngleAxisd(c, Eigen::Vector3d::UnitZ()));
}

std::optional<std::size_t> header_count(const std::string& value) {
  double v = 0.0;
  if (!try_parse_number(trim(value), v) || v < 0 || v != std::floor(v)) return std::nullopt;
  return static_cast<std::size_t>(v);
}

}  // namespace

PoseTrial read_mot(const std::string& path) {
  const TextFile file = read_text_file(path);
  std::optional<bool> in_degrees;
  std::optional<std::size_t> declared_rows;
  std::optional<std::size_t> declared_columns;
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
      in_degrees = value == "yes";
    } else if (key == "nrows" || key == "datarows") {
      declared_rows = header_count(value);
      if (!declared_rows) throw Error(at_line(path, i + 1, "nRows is not a whole number"));
    } else if (key == "ncolumns" || key == "datacolumns") {
      declared_columns = header_count(value);
      if (!declared_columns) throw Error(at_line(path, i + 1, "nColumns is not a whole number"));
    }
  }
  if (i == file.lines.size()) throw Error(path + ": no endheader line (not an OpenSim .mot/.sto)");
  if (!in_degrees) {
    throw Error(at_line(path, i + 1, "header lacks inDegrees=yes|no, so angle units are unknown"));
  }
  ++i;
  while (i < file.lines.size() && is_blank(file.lines[i])) ++i;
  if (i == file.lines.size()) throw Error(path + ": no column names after endheader");
  const std::size_t names_line = i + 1;
  const std::vector<std::string> names = split_whitespace(file.lines[i]);
  int time_column = -1;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (to_lower(names[k]) == "time") time_column = static_cast<int>(k);
  }
  if (time_column < 0) throw Error(at_line(path, names_line, "no time column"));
  if (declared_columns && *declared_columns != names.size()) {
    throw Error(at_line(path, names_line, std::to_string(names.size()) +
                                              " column names where nColumns is " +
                                              std::to_string(*declared_columns)));
  }
  const std::array<int, 6> slot = free_joint_columns(names, time_column, path, names_line);
  const bool has_position = slot[3] >= 0;
  const double angle_scale = *in_degrees ? kPi / 180.0 : 1.0;

  PoseTrial trial;
  trial.path = path;
  const std::string extension = to_lower(std::filesystem::path(path).extension().string());
  trial.format = extension == ".sto" ? "sto" : "mot";
  std::vector<std::size_t> line_numbers;
  for (++i; i < file.lines.size(); ++i) {
    if (is_blank(file.lines[i])) continue;
    const std::size_t line = i + 1;
    const std::vector<std::string> cells = split_whitespace(file.lines[i]);
    if (cells.size() != names.size()) {
      throw Error(at_line(path, line, std::to_string(cells.size()) + " cells where the header names " +
                                          std::to_string(names.size()) +
                                          " columns (truncated or malformed row)"));
    }
    auto value = [&](int column) {
      const double v = parse_number(cells[column], path, line, names[column]);
      if (!std::isfinite(v)) {
        throw Error(at_line(path, line, "column " + names[column] + " is not finite"));
      }
      return v;
    };
    trial.time_s.push_back(value(time_column));
    trial.orientation.push_back(cardan_xyz(value(slot[0]) * angle_scale,
                                           value(slot[1]) * angle_scale,
                                           value(slot[2]) * angle_scale));
    if (has_position) trial.position_m.emplace_back(value(slot[3]), value(slot[4]), value(slot[5]));
    line_numbers.push_back(line);
  }
  if (trial.time_s.empty()) throw Error(path + ": no rows after the column names");
  if (declared_rows && *declared_rows != trial.time_s.size()) {
    throw Error(path + ": holds " + std::to_string(trial.time_s.size()) + " rows where nRows is " +
                std::to_string(*declared_rows) +
                (trial.time_s.size() < *declared_rows ? " (truncated file?)" : ""));
  }
  check_time_stamps(trial.time_s, path, line_numbers);
  make_hemispheres_continuous(trial.orientation);
  return trial;
}

PoseTrial read_pose_csv(const std::string& path) {
  const TextFile file = read_text_file(path);
  std::size_t i = 0;
  while (is_blank(file.lines[i])) ++i;
  const std::size_t header_line = i + 1;
  const std::vector<std::string> header = split_csv_line(file.lines[i], path, header_line);
  auto find = [&](const char* name) {
    for (std::size_t k = 0; k < header.size(); ++k) {
      if (to_lower(trim(header[k])) == name) return static_cast<int>(k);
    }
    return -1;
  };
  const int t = find("t");
  const int q[4] = {find("qw"), find("qx"), find("qy"), find("qz")};
  const int p[3] = {find("x"), find("y"), find("z")};
  if (t < 0 || q[0] < 0 || q[1] < 0 || q[2] < 0 || q[3] < 0) {
    throw Error(at_line(path, header_line, "header must hold t,qw,qx,qy,qz[,x,y,z]"));
  }
  const int positions = (p[0] >= 0) + (p[1] >= 0) + (p[2] >= 0);
  if (positions != 0 && positions != 3) {
    throw Error(at_line(path, header_line, "position needs all of x, y, z or none"));
  }

  PoseTrial trial;
  trial.path = path;
  trial.format = "pose_csv";
  std::vector<std::size_t> line_numbers;
  for (++i; i < file.lines.size(); ++i) {
    if (is_blank(file.lines[i])) continue;
    const std::size_t line = i + 1;
    const std::vector<std::string> cells = split_csv_line(file.lines[i], path, line);
    if (cells.size() != header.size()) {
      throw Error(at_line(path, line, std::to_string(cells.size()) + " cells where the header has " +
                                          std::to_string(header.size()) +
                                          " (truncated or malformed row)"));
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

}  // namespace aloft::host
