// An accelerometer's units checked from the physics: at rest it reads gravity, 9.81 m/s²,
// or about 1 when it is in g. A log in g read as m/s² once made a whole session one
// long flight (the flight detector saw free fall everywhere), so such a log is refused
// with the option that converts it, before any flight is looked for.
#pragma once

#include "common/trial.hpp"

namespace aloft::host {

// The accelerometer's magnitude at rest: the median over stretches of 50 samples where the
// body turns at most 2 (rad/s or °/s alike: a throw turns faster) and the magnitude holds
// within 2 %. 0 when the log has no accelerometer or no such stretch.
double accel_at_rest(const ImuLog& log);

// Throws aloft::host::Error, one line naming the log and --accel-units g, when the
// accelerometer reads between 0.85 and 1.15 at rest.
void check_accel_units(const ImuLog& log);

}  // namespace aloft::host
