#include "readers/imu_csv_reader.hpp"

#include <cmath>
#include <optional>
#include <utility>

#include "common/commands.hpp"
#include "common/file_error.hpp"
#include "readers/text_cells.hpp"
#include "readers/time_stamps.hpp"

namespace aloft::host {

namespace {

// Column indices of the recognised layout.
struct ImuColumns {
  std::string format;
  int time = -1;
  int gyro[3] = {-1, -1, -1};
  int accel[3] = {-1, -1, -1};
  int rotor = -1;  // plain layout only: rotor_rad_s
};

int find_column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (to_lower(header[i]) == name) return static_cast<int>(i);
  }
  return -1;
}

std::optional<ImuColumns> recognise_plain(const std::vector<std::string>& header) {
  ImuColumns c;
  c.format = "imu_csv";
  c.time = find_column(header, "t");
  const char* gyro[3] = {"gx", "gy", "gz"};
  const char* accel[3] = {"ax", "ay", "az"};
  for (int k = 0; k < 3; ++k) {
    c.gyro[k] = find_column(header, gyro[k]);
    c.accel[k] = find_column(header, accel[k]);
  }
  c.rotor = find_column(header, "rotor_rad_s");
  if (c.time < 0 || c.gyro[0] < 0 || c.gyro[1] < 0 || c.gyro[2] < 0) return std::nullopt;
  return c;
}

std::optional<ImuColumns> recognise_phyphox(const std::vector<std::string>& header) {
  ImuColumns c;
  c.format = "phyphox";
  c.time = find_column(header, "time (s)");
  const char* gyro[3] = {"gyroscope x (rad/s)", "gyroscope y (rad/s)", "gyroscope z (rad/s)"};
  // phyphox's combined-sensor exports name the accelerometer like this.
  const char* accel[3] = {"acceleration x (m/s^2)", "acceleration y (m/s^2)", "acceleration z (m/s^2)"};
  for (int k = 0; k < 3; ++k) {
    c.gyro[k] = find_column(header, gyro[k]);
    c.accel[k] = find_column(header, accel[k]);
  }
  if (c.time < 0 || c.gyro[0] < 0 || c.gyro[1] < 0 || c.gyro[2] < 0) return std::nullopt;
  return c;
}

// The layout a header row names; throws "FILE:LINE: ..." for any other header.
ImuColumns recognise_header(const std::vector<std::string>& header, const std::string& path,
                            std::size_t header_line) {
  std::optional<ImuColumns> columns = recognise_plain(header);
  if (!columns) columns = recognise_phyphox(header);
  if (!columns) {
    throw Error(at_line(path, header_line,
                        "header is neither a plain IMU log (t,gx,gy,gz[,ax,ay,az][,rotor_rad_s]) nor a "
                        "phyphox export (\"Time (s)\",\"Gyroscope x (rad/s)\",...), delimited by "
                        "commas, semicolons or tabs"));
  }
  const int accel_found = (columns->accel[0] >= 0) + (columns->accel[1] >= 0) + (columns->accel[2] >= 0);
  if (accel_found != 0 && accel_found != 3) {
    throw Error(at_line(path, header_line, "accelerometer needs all three columns or none"));
  }
  return *columns;
}

}  // namespace

static ImuLog read_imu_csv_unguarded(const std::string& path) {
  const TextFile file = read_text_file(path, [&](const std::string& line, std::size_t number) {
    recognise_header(split_csv_line(line, path, number, 0, csv_delimiter(line)), path, number);
  });
  std::size_t header_index = 0;
  while (is_blank(file.lines[header_index])) ++header_index;
  const std::size_t header_line = header_index + 1;
  const char delimiter = csv_delimiter(file.lines[header_index]);
  const std::vector<std::string> header =
      split_csv_line(file.lines[header_index], path, header_line, 0, delimiter);
  const std::optional<ImuColumns> columns = recognise_header(header, path, header_line);
  const bool has_accel = columns->accel[0] >= 0;

  ImuLog log;
  log.path = path;
  log.format = columns->format;
  std::vector<std::size_t> line_numbers;
  for (std::size_t i = header_index + 1; i < file.lines.size(); ++i) {
    if (is_blank(file.lines[i])) continue;
    const std::size_t line = i + 1;
    const std::vector<std::string> cells = split_csv_line(file.lines[i], path, line, 0, delimiter);
    if (cells.size() != header.size()) {
      throw Error(at_line(path, line,
                          std::to_string(cells.size()) + " cells where the header has " +
                              std::to_string(header.size()) + " (truncated or malformed row)"));
    }
    auto value = [&](int column) {
      // A file delimited by ';' or tabs may write its numbers with a decimal comma.
      const std::string& cell = cells[column];
      const double v =
          parse_number(delimiter == ',' ? cell : with_decimal_point(cell), path, line, header[column]);
      if (!std::isfinite(v)) {
        throw Error(
            at_line(path, line, "column " + header[column] + " is not finite ('" + cells[column] + "')"));
      }
      return v;
    };
    log.time_s.push_back(value(columns->time));
    log.gyro_rad_s.emplace_back(value(columns->gyro[0]), value(columns->gyro[1]), value(columns->gyro[2]));
    if (has_accel) {
      log.accel_m_s2.emplace_back(value(columns->accel[0]), value(columns->accel[1]),
                                  value(columns->accel[2]));
    }
    if (columns->rotor >= 0) log.rotor_rad_s.push_back(value(columns->rotor));
    line_numbers.push_back(line);
  }
  if (log.time_s.empty()) throw Error(path + ": no samples after the header");
  check_time_stamps(log.time_s, path, line_numbers);
  log.header_line = header_line;
  log.line_numbers = std::move(line_numbers);
  return log;
}

ImuLog read_imu_csv(const std::string& path) {
  return with_file_context(path, [&] { return read_imu_csv_unguarded(path); });
}

}  // namespace aloft::host
