// An `impulse` verdict checked against the accelerometer (issue 31 item 4). A blow from
// outside (a hit, a bounce, a string) that changes the angular momentum by L pushes the
// centre of mass too: it acts at a point c of the surface, with a linear impulse P where
// c x P = L, and the accelerometer reads P/m over the blow, beyond what the rotation
// explains. The gyro's fit cannot tell a blow from a shift inside the body or from a fit
// that put a step where the model lacks something else; the accelerometer can.
#pragma once

#include <optional>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/4_judge/analysis.hpp"

namespace aloft::host::diagnose {

// The blow is measured as the velocity change it gives the centre of mass: the integral
// of a - K r over a window about the fitted impulse time. The integral, not the peak: the
// tangential term w_dot x r of a step in w is as sharp as the step, and w_dot from gyro
// differences blurs it over a few ms, so sample by sample an inner step leaves a residual
// as large as a blow's; over a window wider than the blur, the sum of the differences is
// the step in w itself, and only a force from outside remains.
//   - Half-width of the window: the impulse time search refines to a sample, a blow lasts
//     a few ms (the generator's 3 ms), and w_dot spans 2 ms either side.
constexpr double kImpulseWindow_s = 0.015;
//   - Seen when the velocity change is this many times the RMS of the same integral over
//     the rest of the flight (windows side by side, the impulse's own left out): what the
//     accelerometer's noise, its drift and the blurred w_dot give where nothing happens.
//     Chosen on 12 generated 3 ms impulses (4 bodies x seeds 70-72,
//     tests/diagnose/test_impulse_force_check.cpp): a blow reads 6.7-30 times that, the
//     same steps made inside the body 0.3-2.2, and 4 lies between. On seeds 170-175, not
//     looked at while choosing, 45 of 48 decisions are right (blows at 2.5 and 3.5 x
//     missed, one inner step at 4.2 x).
constexpr double kSeenOverElsewhere = 4.0;

struct ImpulseForce {
  double velocity_change_m_s = 0.0;  // |integral of (a - K r - its flight mean)| over the window
  double elsewhere_rms_m_s = 0.0;    // the same integral's RMS over the rest of the flight
  bool seen = false;
};

// The accelerometer about the impulse time; none when the flight has no accelerometer or
// is too short for windows elsewhere. r is the body file's imu.position, else a
// least-squares fit over the flight (aloft/onboard/lever_arm_estimate.hpp).
std::optional<ImpulseForce> impulse_force(const Flight& flight, double impulse_time_s);

// For each impulse of the verdict: a note of what the accelerometer shows; where it shows
// no blow, the verdict is not confident and says why.
void check_impulse_against_accelerometer(Analysis& analysis, const Flight& flight);

}  // namespace aloft::host::diagnose
