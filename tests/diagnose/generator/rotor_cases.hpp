// Sessions for `internal_momentum` (issue 31): rotor sessions and sessions where a rotor
// is absent but looks close, on three seed ranges: one to tune on, one withheld (never
// tuned on; the figures in docs/validation/diagnose-accuracy.md are measured there), and a fresh one,
// measured once after the large rotor's fit starts were repaired on failures seen on the other two.
//
// A session is several flights of one body and one sensor sharing one effect (the effect
// drawn once from the session's seed, each throw and its noise from its own seed:
// FlightSpec::throw_seed), gyro at 1 kHz unless said:
//   rotor        internal_momentum, every body in turn (flight_generator.hpp: |h| 0.5-10 %
//                of |L| at 10 rad/s, any direction);
//   impulse      an impulse in each flight (its size and time drawn once, relative to
//                each throw);
//   moments      wrong moments on the two bodies of revolution (cylinder, disc), where an
//                axial moment change is, flight by flight, a rotor along the axis;
//   noise        noise alone behind a 1 kHz gyro's 20 Hz low-pass (the flight the
//                previous rotor named `impulse`);
//   bias         a gyro bias, which a rotor h = I·b mimics to first order (listed after
//                the others, whose seeds stay as they were);
//   filtered     a rotor behind a 100 Hz two-pole low-pass, at 1 kHz and 4 kHz in turn
//                (listed after those, for the same reason);
//   rotor_moments a rotor on a body whose nominal moments are also 5-20 % off, every
//                body in turn (a wheel in a body whose tensor came from CAD);
//   stopped      the same bodies with the wheel stopped: wrong moments alone;
//   large_rotor  a rotor of 40-100 % of |L|, where a fit from zero can stop in another
//                minimum;
//   large_rotor_moments a rotor of 15-40 % of |L| with the moments 5-20 % off, every body
//                in turn (listed last), where one flight's own fit of the pair can stop
//                in another minimum.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "flight_generator.hpp"

namespace aloft::generator {

struct SessionCase {
  std::string name;                 // e.g. "rotor_3": unique
  std::vector<FlightSpec> flights;  // one spec per flight (throw_seed set)
  std::uint64_t seed = 0;           // the effect's seed, shared by the flights
};

// unseen: drawn only after the spin-up's per-flight profile was written, never looked at
// while tuning it.
enum class RotorSeeds { tuning, withheld, fresh, unseen };

// `per_kind` sessions of each kind, of `flights` flights each.
std::vector<SessionCase> rotor_session_cases(RotorSeeds seeds, int per_kind, int flights);

}  // namespace aloft::generator
