// Phone-like flights and sessions (issue 8, item 6): the withheld-effect flights of
// flight_generator.hpp as a phone's gyro logs them (phone_gyro.hpp), lying still before
// and after, with the flights marked by a segments file (SPEC §3).
//
// The phone (drawn from the seed): gyro at 100-500 Hz with +-2 % timestamp jitter, a
// causal second-order Butterworth low-pass at 15-40 Hz applied before the noise, white
// noise 0.005-0.02 rad/s per axis, 1 mrad/s quantisation. The flight's sensor model
// (bias, scale, axes, clock) acts before the filter, as inside a real sensor.
// Rest: 1-2 s before and after each flight, the phone lying still (zero true rate, so
// the reading is the gyro's bias, if any) with the same filter, noise and quantisation.
// The hand spins the body up from rest in 0.1-0.2 s (the rate ramps to the release's)
// and stops it in 0.03-0.05 s after the catch; the filter carries the spin-up into the
// first tens of milliseconds of the flight.
//
// A session: several flights of one body with one true effect (the effect drawn once
// from the seed, each flight's throw and noise from its own seed: FlightSpec::throw_seed)
// in one log, rest between; its segments file also holds a keep=false row whose start and
// end are blank, as phyphox users leave them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "flight_generator.hpp"
#include "phone_gyro.hpp"

namespace aloft::generator {

struct PhoneLikeFlight {
  GeneratedFlight flight;  // nominal body and truth; flight.imu is the phone's whole log
  host::Segment window;    // release to catch, on the log's clock
  PhoneGyroSpec gyro;
  std::string segments_csv;  // the one-row segments file (SPEC §3)
};
// truth.onset_s and an impulse's params.time_s are moved onto the log's clock; the true
// samples keep the flight's own clock (t = 0 at release).
PhoneLikeFlight generate_phone_like_flight(const FlightSpec& spec, std::uint64_t seed);

struct PhoneLikeSession {
  GeneratedFlight first;            // nominal body and the truth of the first flight
  std::vector<FlightTruth> truths;  // per flight (same effect class and body)
  host::ImuLog log;
  std::vector<host::Segment> flights;  // the kept rows, on the log's clock
  PhoneGyroSpec gyro;
  std::string segments_csv;  // the flights and one keep=false row with blank start/end
};
PhoneLikeSession generate_phone_like_session(const FlightSpec& spec, int flights, std::uint64_t seed);

}  // namespace aloft::generator
