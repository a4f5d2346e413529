#include "replay/imu_csv_recording.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "common/commands.hpp"
#include "readers/imu_csv_reader.hpp"
#include "readers/text_cells.hpp"
#include "readers/time_stamps.hpp"

namespace aloft::host {
namespace {

Vec3<float> as_float(const Eigen::Vector3d& v) { return v.cast<float>(); }

// Whole microseconds after the first sample. The pipeline takes every dt from these, so
// two samples closer than half a microsecond would make a zero step: refused here.
std::uint64_t microseconds_after_first(const ImuLog& log, std::size_t i) {
  const double us = std::round((log.time_s[i] - log.time_s[0]) * 1e6);
  if (!(us < 1.8e19))
    throw Error(at_line(log.path, log.line_numbers[i], "time stamp too far from the first"));
  return static_cast<std::uint64_t>(us);
}

}  // namespace

Recording read_imu_csv_recording(const std::string& path) { return imu_csv_recording(read_imu_csv(path)); }

Recording imu_csv_recording(const ImuLog& log) {
  const std::string& path = log.path;
  if (log.accel_m_s2.empty()) {
    throw Error(
        at_line(path, log.header_line,
                "no accelerometer columns ax,ay,az; aloft replay tells release and landing from them"));
  }
  Recording recording;
  recording.path = path;
  recording.format = "imu_csv";
  recording.t0_s = log.time_s[0];
  recording.t0_us = log.time_s[0] > 0.0 ? static_cast<std::uint64_t>(std::llround(log.time_s[0] * 1e6)) : 0;
  recording.has_rotor_speed = !log.rotor_rad_s.empty();
  for (const double w : log.rotor_rad_s)
    recording.max_abs_rotor_rad_s = std::max(recording.max_abs_rotor_rad_s, std::abs(w));
  const std::vector<char> gap_after = steps_followed_by_gap(log.time_s);
  recording.samples.reserve(log.time_s.size());
  for (std::size_t i = 0; i < log.time_s.size(); ++i) {
    ImuSample<float> s;
    s.t_us = microseconds_after_first(log, i);
    if (i > 0 && s.t_us <= recording.samples.back().t_us) {
      throw Error(at_line(path, log.line_numbers[i], "less than a microsecond after the previous sample"));
    }
    s.gyro_rad_s = as_float(log.gyro_rad_s[i]);
    s.accel_m_s2 = as_float(log.accel_m_s2[i]);
    if (!all_finite(s.gyro_rad_s) || !all_finite(s.accel_m_s2)) {
      throw Error(at_line(path, log.line_numbers[i], "a value beyond single precision's range"));
    }
    if (recording.has_rotor_speed) {
      s.rotor_rad_s = static_cast<float>(log.rotor_rad_s[i]);
      if (!std::isfinite(s.rotor_rad_s)) {
        throw Error(at_line(path, log.line_numbers[i], "rotor_rad_s beyond single precision's range"));
      }
      s.flags |= imu_rotor_speed;
    }
    if (i > 0 && gap_after[i - 1]) s.flags |= imu_gap_before;
    recording.samples.push_back(s);
  }
  return recording;
}

}  // namespace aloft::host
