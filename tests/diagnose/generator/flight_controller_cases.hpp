// Sessions logged as a flight controller logs its gyro (issue 44): a rate of 1, 2, 4 or
// 8 kHz, a first-order PT1 low-pass at 50-250 Hz (Betaflight's gyro filter; the ICM-42688's
// UI filter at order 1), readings quantised to 1/16.4 deg/s (the ICM-42688's and MPU-6000's
// step at +-2000 deg/s), one sensor for the session's flights, each flight's throw and
// noise its own. Kinds, each on every body in turn:
//   spin_up     a rotor a motor spins up from rest after release (rotor_spin_up.hpp):
//               one axis and |h| for the session (5-40 % of the |L| the body carries at
//               10 rad/s), each throw its own start (20-80 ms), time constant (40-80 ms)
//               and final speed (+-15 %); as a first-order step, or as a ramp or a
//               smooth step rising over 3 time constants (`shape`: rotor_spin_up.hpp);
//   and its look-alikes, with no rotor:
//   moments     wrong moments (5-20 %);
//   misaligned  the sensor turned 3-15 deg from the body's axes;
//   stopped     the wheel at rest: the nominal body and noise alone;
//   impulse     a knock in each flight (its size and time relative to each throw).
#pragma once

#include <cstdint>
#include <vector>

#include "rotor_cases.hpp"

namespace aloft::generator {

// The flight controller's gyro: kFlightControllerStep, its logged resolution in rad/s.
constexpr double kFlightControllerStep = 3.14159265358979323846 / 180.0 / 16.4;

// A flight spec logged by a flight controller at `rate_hz` behind a PT1 at `cutoff_hz`.
FlightSpec flight_controller_spec(const std::string& effect, const std::string& body, double rate_hz,
                                  double cutoff_hz);

// `per_kind` sessions of each kind, of `flights` flights each (RotorSeeds: seed sets of
// their own, far from rotor_cases.hpp's).
std::vector<SessionCase> flight_controller_session_cases(RotorSeeds seeds, int per_kind, int flights,
                                                         SpinUpShape shape = SpinUpShape::first_order);
// The same from any first seed: a set never drawn before (the named sets' first seeds are
// 44010000, 44090000, 44170000 and 44250000).
std::vector<SessionCase> flight_controller_session_cases(std::uint64_t first_seed, int per_kind, int flights,
                                                         SpinUpShape shape = SpinUpShape::first_order);

}  // namespace aloft::generator
