// A body file and a recording must agree on the rotor (SPEC §2 `rotor`, §3 `rotor_rad_s`).
// The rotor's torque on the body, -dh/dt - ω × h with h = J · speed · axis, is known only
// from both: the body file's J and axis and the recording's speed. So:
//   - a body with a rotor and a recording without its speed (a CSV without `rotor_rad_s`,
//     or any FIFO recording: the sensor's FIFO holds no rotor) is refused: the flight's
//     torque is unknown, and a rotor spinning up would read as a landing or bias the
//     tensor, without a word;
//   - a recording with the speed and a body without a rotor is refused as well (SPEC §3),
//     unless the speed is 0 in every sample: a rotor that never turned has no momentum
//     and no torque, so the flight is what it would be without it; then a warning says
//     the column is ignored (the speeds are taken out of the samples).
// Each refusal is one line that names both files and what to add.
#pragma once

#include <string>

#include "common/body_file.hpp"
#include "replay/recording.hpp"

namespace aloft::host {

// Throws Error (one line naming `body_source` and the recording) or warns, as above.
void check_rotor_matches(const Body& body, const std::string& body_source, Recording& recording);

}  // namespace aloft::host
