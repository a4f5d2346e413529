#include "readers/trc_reader.hpp"

#include <cmath>
#include <limits>
#include <map>

#include "common/commands.hpp"
#include "common/file_error.hpp"
#include "common/warning.hpp"
#include "readers/length_units.hpp"
#include "readers/text_cells.hpp"
#include "readers/time_stamps.hpp"

namespace aloft::host {

namespace {

constexpr std::size_t kFirstHeaderLines = 5;

// The cells of a header line without the empty ones: some writers (OpenSim's Rajagopal
// pipeline) separate header cells with two tabs, and OpenSim's own reader drops the
// empty cells that leaves.
std::vector<std::string> nonempty_tab_cells(const std::string& line) {
  std::vector<std::string> cells;
  for (std::string& cell : split_tab_line(line)) {
    if (!cell.empty()) cells.push_back(std::move(cell));
  }
  return cells;
}

// Keys of line 2 with the values of line 3.
std::map<std::string, std::string> header_values(const TextFile& file) {
  const std::vector<std::string> keys = nonempty_tab_cells(file.lines[1]);
  const std::vector<std::string> values = nonempty_tab_cells(file.lines[2]);
  std::map<std::string, std::string> out;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    out[to_lower(keys[i])] = i < values.size() ? values[i] : std::string();
  }
  return out;
}

double header_number(const std::map<std::string, std::string>& header, const std::string& key,
                     const std::string& path) {
  const auto it = header.find(to_lower(key));
  if (it == header.end()) throw Error(at_line(path, 2, "header has no " + key));
  double value = 0.0;
  if (!try_parse_number(it->second, value) || !std::isfinite(value)) {
    throw Error(at_line(path, 3, key + " '" + it->second + "' is not a number"));
  }
  return value;
}

std::size_t header_count(const std::map<std::string, std::string>& header, const std::string& key,
                         const std::string& path) {
  const double value = header_number(header, key, path);
  if (value < 0 || value != std::floor(value) || value > 1e9) {
    throw Error(at_line(path, 3, key + " must be a whole number, not '" + header.at(to_lower(key)) + "'"));
  }
  return static_cast<std::size_t>(value);
}

// Line 4's marker names after Frame# and Time, as many as NumMarkers declares.
std::vector<std::string> read_marker_names(const TextFile& file, std::size_t declared_markers,
                                           const std::string& path) {
  const std::vector<std::string> names_row = split_tab_line(file.lines[3]);
  if (names_row.size() < 2 || to_lower(names_row[0]) != "frame#" || to_lower(names_row[1]) != "time") {
    throw Error(at_line(path, 4, "marker header must start with Frame# and Time"));
  }
  std::vector<std::string> names;
  for (std::size_t i = 2; i < names_row.size(); ++i) {
    if (!names_row[i].empty()) names.push_back(names_row[i]);
  }
  if (names.size() != declared_markers) {
    throw Error(at_line(path, 4,
                        "names " + std::to_string(names.size()) + " markers where NumMarkers is " +
                            std::to_string(declared_markers)));
  }
  if (names.empty()) throw Error(at_line(path, 4, "no marker names"));
  return names;
}

// One row's markers in metres (`scale` per unit of the file); a marker with no
// coordinates is missing (NaN), one with some of them is refused.
std::vector<Eigen::Vector3d> frame_markers(const std::vector<std::string>& cells,
                                           const std::vector<std::string>& names, double scale,
                                           const std::string& path, std::size_t line) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Eigen::Vector3d> frame(names.size());
  for (std::size_t m = 0; m < names.size(); ++m) {
    double xyz[3];
    int present = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const std::string& cell = cells[2 + 3 * m + static_cast<std::size_t>(axis)];
      const std::string column = names[m] + " " + "XYZ"[axis];
      xyz[axis] = cell.empty() ? nan : parse_number(cell, path, line, column);
      if (std::isinf(xyz[axis])) {
        throw Error(at_line(path, line, "column " + column + " is infinite"));
      }
      present += std::isfinite(xyz[axis]) ? 1 : 0;
    }
    if (present != 0 && present != 3) {
      throw Error(at_line(path, line, "marker " + names[m] + " has only some of X, Y, Z"));
    }
    frame[m] = present == 3 ? Eigen::Vector3d(xyz[0] * scale, xyz[1] * scale, xyz[2] * scale)
                            : Eigen::Vector3d(nan, nan, nan);
  }
  return frame;
}

// Every row after the header into `trial`, which holds the marker names; returns the
// line number of each row, for messages about its time stamp.
std::vector<std::size_t> read_frames(const TextFile& file, double scale, const std::string& path,
                                     MarkerTrial& trial) {
  const std::size_t cells_per_row = 2 + 3 * trial.marker_names.size();
  std::vector<std::size_t> line_numbers;
  for (std::size_t i = kFirstHeaderLines; i < file.lines.size(); ++i) {
    if (is_blank(file.lines[i])) continue;
    const std::size_t line = i + 1;
    const std::vector<std::string> cells = split_tab_line(file.lines[i]);
    if (cells.size() < cells_per_row) {
      throw Error(at_line(path, line,
                          std::to_string(cells.size()) + " cells where a frame has " +
                              std::to_string(cells_per_row) + " (truncated or malformed row)"));
    }
    for (std::size_t k = cells_per_row; k < cells.size(); ++k) {
      if (!cells[k].empty()) {
        throw Error(at_line(path, line, "more coordinates than NumMarkers declares"));
      }
    }
    parse_number(cells[0], path, line, "Frame#");
    trial.time_s.push_back(parse_number(cells[1], path, line, "Time"));
    trial.positions_m.push_back(frame_markers(cells, trial.marker_names, scale, path, line));
    line_numbers.push_back(line);
  }
  return line_numbers;
}

}  // namespace

static MarkerTrial read_trc_unguarded(const std::string& path) {
  const auto check_first_line = [&](const std::string& line, std::size_t number) {
    if (number != 1 || to_lower(line).rfind("pathfiletype", 0) != 0) {
      throw Error(at_line(path, 1, "not a TRC file: first line must start with PathFileType"));
    }
  };
  const TextFile file = read_text_file(path, check_first_line);
  if (file.lines.size() < kFirstHeaderLines) {
    throw Error(path + ": header ends early (a TRC header has five lines)");
  }
  const auto header = header_values(file);

  MarkerTrial trial;
  trial.path = path;
  trial.format = "trc";
  const auto rate_key = header.count("datarate") ? "DataRate" : "CameraRate";
  trial.rate_hz = header_number(header, rate_key, path);
  if (!(trial.rate_hz > 0.0)) throw Error(at_line(path, 3, std::string(rate_key) + " must be positive"));
  const std::size_t declared_frames = header_count(header, "NumFrames", path);
  const std::size_t declared_markers = header_count(header, "NumMarkers", path);
  const auto units = header.find("units");
  if (units == header.end()) throw Error(at_line(path, 2, "header has no Units"));
  const double scale = metres_per_unit(units->second);
  if (scale == 0.0) {
    throw Error(at_line(path, 3, "unknown units '" + units->second + "' (expected mm, cm or m)"));
  }
  trial.units_in_file = trim(units->second);
  trial.marker_names = read_marker_names(file, declared_markers, path);

  const std::vector<std::size_t> line_numbers = read_frames(file, scale, path, trial);
  if (trial.time_s.empty()) throw Error(path + ": no frames after the header");
  if (trial.time_s.size() != declared_frames) {
    // OpenSim reads the rows present whatever NumFrames claims, and so do we; every row
    // read is whole (read_frames refuses a row cut short), so only the count is off.
    warn(path + ": holds " + std::to_string(trial.time_s.size()) + " frames where NumFrames is " +
         std::to_string(declared_frames) + "; reading the " + std::to_string(trial.time_s.size()) +
         " present");
  }
  check_time_stamps(trial.time_s, path, line_numbers);
  return trial;
}

MarkerTrial read_trc(const std::string& path) {
  return with_file_context(path, [&] { return read_trc_unguarded(path); });
}

}  // namespace aloft::host
