#include "replay/rotor_match.hpp"

#include <cstdint>

#include "common/commands.hpp"
#include "common/warning.hpp"

namespace aloft::host {

void check_rotor_matches(const Body& body, const std::string& body_source, Recording& recording) {
  if (body.rotor && !recording.has_rotor_speed) {
    const std::string what = recording.format == "imu_csv"
                                 ? "has no rotor_rad_s column"
                                 : "holds no rotor speed (a " + recording.format + " recording has none)";
    throw Error(body_source + ": the body has a \"rotor\", but " + recording.path + " " + what +
                ": without the rotor's speed its torque on the body is unknown (log the speed as "
                "rotor_rad_s, or replay with a body file without the rotor if it did not turn)");
  }
  if (!body.rotor && recording.has_rotor_speed) {
    if (recording.max_abs_rotor_rad_s == 0.0) {
      warn(recording.path + ": rotor_rad_s is 0 in every sample and " + body_source +
           " has no \"rotor\": the column is ignored");
      for (ImuSample<float>& s : recording.samples) {
        s.rotor_rad_s = 0.0f;
        s.flags = static_cast<std::uint8_t>(s.flags & ~imu_rotor_speed);
      }
      recording.has_rotor_speed = false;
      return;
    }
    throw Error(recording.path + ": a rotor_rad_s column (the rotor turns), but " + body_source +
                " has no \"rotor\": add its \"inertia_kg_m2\" and \"axis\" (docs/file-formats.md); "
                "without them its torque on the body is unknown");
  }
}

}  // namespace aloft::host
