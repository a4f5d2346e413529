#include "diagnose/1_input/airborne_windows.hpp"

#include <cstdio>

#include "replay/imu_csv_recording.hpp"
#include "replay/replay_run.hpp"

namespace aloft::host::diagnose {
namespace {

std::string how_found(const FlightResult<float>& flight) {
  char text[96];
  std::snprintf(text, sizeof text, "found by the firmware's release and landing code (imu.position %s)",
                flight.imu_position_estimated ? "estimated" : "given");
  return text;
}

}  // namespace

std::vector<Segment> airborne_windows(const ImuLog& log, const Body& body, const std::string& body_source) {
  std::vector<Segment> out;
  if (log.time_s.empty() || log.accel_m_s2.size() != log.time_s.size()) return out;
  const Recording recording = imu_csv_recording(log);
  const ReplayResult replay = run_replay(replay_settings_from_body(body), body_source, recording);
  for (const FlightResult<float>& flight : replay.flights) {
    const double from = recording_time_s(replay, flight.release_us);
    const double to = flight.landed ? recording_time_s(replay, flight.landing_us) : log.time_s.back();
    if (to - from < kShortestFlight_s) continue;
    out.push_back({"airborne" + std::to_string(out.size() + 1), from, to, how_found(flight)});
  }
  return out;
}

}  // namespace aloft::host::diagnose
