#include "readers/imu_window.hpp"

#include <algorithm>
#include <sstream>

#include "common/commands.hpp"

namespace aloft::host {

ImuLog imu_window(const ImuLog& log, double start_s, double end_s, const std::string& label) {
  const auto first = std::lower_bound(log.time_s.begin(), log.time_s.end(), start_s);
  const auto last = std::upper_bound(log.time_s.begin(), log.time_s.end(), end_s);
  const auto begin_index = first - log.time_s.begin();
  const auto end_index = std::max(begin_index, last - log.time_s.begin());
  if (end_index - begin_index < 2) {
    std::ostringstream message;
    message << log.path << ": " << label << " (" << start_s << "–" << end_s << " s) holds "
            << (end_index - begin_index) << " samples";
    if (!log.time_s.empty()) {
      message << "; the log spans " << log.time_s.front() << "–" << log.time_s.back() << " s";
    }
    throw Error(message.str());
  }
  ImuLog window;
  window.path = log.path;
  window.format = log.format;
  window.time_s.assign(log.time_s.begin() + begin_index, log.time_s.begin() + end_index);
  window.gyro_rad_s.assign(log.gyro_rad_s.begin() + begin_index, log.gyro_rad_s.begin() + end_index);
  if (!log.accel_m_s2.empty()) {
    window.accel_m_s2.assign(log.accel_m_s2.begin() + begin_index, log.accel_m_s2.begin() + end_index);
  }
  if (!log.rotor_rad_s.empty()) {
    window.rotor_rad_s.assign(log.rotor_rad_s.begin() + begin_index, log.rotor_rad_s.begin() + end_index);
  }
  return window;
}

}  // namespace aloft::host
