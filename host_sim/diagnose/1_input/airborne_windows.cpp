#include "diagnose/1_input/airborne_windows.hpp"

#include "replay/imu_csv_recording.hpp"
#include "replay/replay_run.hpp"

namespace aloft::host::diagnose {

std::vector<FirmwareFlight> firmware_flights(const ImuLog& log, const Body& body,
                                             const std::string& body_source) {
  std::vector<FirmwareFlight> out;
  if (log.time_s.empty() || log.accel_m_s2.size() != log.time_s.size()) return out;
  const Recording recording = imu_csv_recording(log);
  const ReplayResult replay = run_replay(replay_settings_from_body(body), body_source, recording);
  for (const FlightResult<float>& flight : replay.flights) {
    FirmwareFlight f;
    f.release_s = recording_time_s(replay, flight.release_us);
    f.landed = flight.landed;
    f.landing_s = flight.landed ? recording_time_s(replay, flight.landing_us) : log.time_s.back();
    f.imu_position_m = flight.imu_position_m.cast<double>();
    f.imu_position_estimated = flight.imu_position_estimated;
    out.push_back(f);
  }
  return out;
}

std::vector<Segment> airborne_windows(const ImuLog& log, const Body& body, const std::string& body_source) {
  std::vector<Segment> out;
  for (const FirmwareFlight& f : firmware_flights(log, body, body_source)) {
    if (f.landing_s - f.release_s < kShortestFlight_s) continue;
    out.push_back({"airborne" + std::to_string(out.size() + 1), f.release_s, f.landing_s,
                   std::string("found by the firmware's release and landing code (imu.position ") +
                       (f.imu_position_estimated ? "estimated)" : "given)")});
  }
  return out;
}

}  // namespace aloft::host::diagnose
