// The fixed phone-like cases of the withheld-effect test (issue 8, item 6), made by
// phone_like_flights.hpp. The lists and their seeds never change; the diagnosis must not
// look at a case's truth.
//
//   phone-like flights: none × 8, each of the nine effects × 6 = 62 flights; bodies
//     cycle through body_names() (internal_damping skips the cylinder, as in
//     withheld_effect_cases.hpp);
//   sessions: 3 flights each of none, inertia_moments, inertia_axes, gyro_bias,
//     gyro_scale, sensor_misalignment and clock_drift (the effects that belong to a body
//     or a sensor and so are one for a whole session), bodies cycling as above.
#pragma once

#include <vector>

#include "withheld_effect_cases.hpp"

namespace aloft::generator {

std::vector<FlightCase> phone_like_flight_cases();

// (Not rotor_cases.hpp's SessionCase: two classes of one name in one library broke
// std::vector's instantiations, one definition taking the other's place at link time.)
struct PhoneSessionCase {
  FlightCase flight;  // spec and seed of the session (generate_phone_like_session)
  int flights = 3;
};
std::vector<PhoneSessionCase> phone_like_session_cases();

}  // namespace aloft::generator
