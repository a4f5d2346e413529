#include "diagnose/1_input/airborne_windows.hpp"

#include <string>

#include "aloft/flight_detector.hpp"

namespace aloft::host::diagnose {

std::vector<Segment> airborne_windows(const ImuLog& log) {
  std::vector<Segment> out;
  if (log.accel_m_s2.size() != log.time_s.size()) return out;
  const FlightDetectorSettings<double> settings;
  FlightDetector<double> detector(settings);
  std::size_t start = 0;
  int held = 0;  // consecutive samples above free fall while airborne (a catch)
  bool airborne = false;
  auto close = [&](std::size_t last) {
    const double from = log.time_s[start], to = log.time_s[last];
    if (to - from >= kShortestFlight_s) {
      out.push_back({"airborne" + std::to_string(out.size() + 1), from, to, "found by the flight detector"});
    }
    detector.reset();
    airborne = false;
  };
  for (std::size_t k = 0; k < log.time_s.size(); ++k) {
    const Eigen::Vector3d& a = log.accel_m_s2[k];
    const FlightPhase phase = detector.update(a);
    if (!airborne && phase == FlightPhase::airborne) {
      airborne = true;
      held = 0;
      start = k + 1 >= settings.release_samples ? k + 1 - settings.release_samples : 0;
      continue;
    }
    if (!airborne) continue;
    held = a.norm() >= settings.free_fall_below_m_s2 ? held + 1 : 0;
    if (phase == FlightPhase::landed) {
      close(k > 0 ? k - 1 : 0);
    } else if (held >= settings.release_samples) {
      close(k - static_cast<std::size_t>(held));  // the last free-fall sample
    }
  }
  if (airborne && !log.time_s.empty()) close(log.time_s.size() - 1);
  return out;
}

}  // namespace aloft::host::diagnose
