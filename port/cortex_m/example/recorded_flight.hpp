// A recorded flight stored in flash: the gyro samples of one throw and the body's inertia
// tensor. The definition (recorded_flight.cpp in the build folder) is generated at build
// time by host/make_flight_source.cpp from a trial file (see CMakeLists.txt).
#pragma once

#include <cstdint>

namespace aloft_example {

// Time stamps are whole microseconds, as a sensor's timer gives them: differences of
// float seconds would lose a part in 1e4 of a 1 ms step after one second of flight.
struct GyroSample {
  std::uint32_t t_us;
  float omega_rad_s[3];  // gyro axes = body axes
};

extern const char recorded_flight_source[];       // which trial the data came from
extern const float recorded_inertia_kg_m2[3][3];  // body axes, about the centre of mass
extern const GyroSample recorded_flight[];
extern const unsigned recorded_flight_samples;

}  // namespace aloft_example
