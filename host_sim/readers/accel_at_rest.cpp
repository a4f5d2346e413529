#include "readers/accel_at_rest.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "common/commands.hpp"

namespace aloft::host {

double accel_at_rest(const ImuLog& log) {
  constexpr std::size_t kStretch = 50;
  std::vector<double> still;
  if (log.accel_m_s2.size() != log.time_s.size()) return 0.0;
  for (std::size_t i = 0; i + kStretch <= log.time_s.size(); i += kStretch) {
    double sum = 0.0, squares = 0.0, turn = 0.0;
    for (std::size_t k = i; k < i + kStretch; ++k) {
      const double a = log.accel_m_s2[k].norm();
      sum += a;
      squares += a * a;
      turn = std::max(turn, log.gyro_rad_s[k].norm());
    }
    const double mean = sum / kStretch;
    const double spread = std::sqrt(std::max(0.0, squares / kStretch - mean * mean));
    if (turn <= 2.0 && mean > 0.0 && spread <= 0.02 * mean) still.push_back(mean);
  }
  if (still.empty()) return 0.0;
  std::nth_element(still.begin(), still.begin() + static_cast<std::ptrdiff_t>(still.size() / 2), still.end());
  return still[still.size() / 2];
}

void check_accel_units(const ImuLog& log) {
  const double rest = accel_at_rest(log);
  if (rest > 0.85 && rest < 1.15) {
    char reads[32];
    std::snprintf(reads, sizeof reads, "%.2f", rest);
    throw Error(log.path + ": the accelerometer reads " + reads +
                " at rest where gravity reads 9.81 m/s²: it is in g; give --accel-units g");
  }
}

}  // namespace aloft::host
