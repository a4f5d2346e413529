#include "rotor_cases.hpp"

#include "body_catalogue.hpp"

namespace aloft::generator {

std::vector<SessionCase> rotor_session_cases(RotorSeeds seeds, int per_kind, int flights) {
  // Ranges far from every other list's (withheld effects 20240515 on, phone lists, the
  // noise grid 31000 on), spaced by a large odd constant.
  std::uint64_t seed = seeds == RotorSeeds::tuning     ? 31310000ull
                       : seeds == RotorSeeds::withheld ? 31390000ull
                       : seeds == RotorSeeds::fresh    ? 31470000ull
                                                       : 31550000ull;
  const auto next = [&] { return seed += 0x9E3779B1ull; };
  const auto& bodies = body_names();
  std::vector<SessionCase> out;
  const auto add = [&](const std::string& kind, const std::string& effect, const std::string& body,
                       double cutoff_hz, int index, const std::string& second_effect = "") {
    SessionCase c;
    c.name = kind + "_" + std::to_string(index);
    c.seed = next();
    for (int f = 0; f < flights; ++f) {
      FlightSpec spec;
      spec.effect = effect;
      spec.body = body;
      spec.gyro_cutoff_hz = cutoff_hz;
      spec.second_effect = second_effect;
      spec.throw_seed = next();
      c.flights.push_back(spec);
    }
    out.push_back(c);
  };
  for (int i = 0; i < per_kind; ++i) {
    add("rotor", "internal_momentum", bodies[static_cast<std::size_t>(i) % bodies.size()], 0.0, i);
    add("impulse", "impulse", bodies[static_cast<std::size_t>(i + 2) % bodies.size()], 0.0, i);
    add("moments", "inertia_moments", i % 2 == 0 ? "cylinder" : "disc", 0.0, i);
    add("noise", "none", bodies[static_cast<std::size_t>(i + 1) % bodies.size()], 20.0, i);
  }
  // Added after the others, so that their seeds stay those measured before.
  for (int i = 0; i < per_kind; ++i) {
    add("bias", "gyro_bias", bodies[static_cast<std::size_t>(i + 3) % bodies.size()], 0.0, i);
  }
  // Rotors seen through a gyro's 100 Hz two-pole low-pass, at 1 kHz and at 4 kHz (a
  // flight controller's rate): noise correlated over 2-10 samples, whose fits' own
  // covariances understate their errors (between_flight_scatter.hpp widens them).
  for (int i = 0; i < per_kind; ++i) {
    add("filtered", "internal_momentum", bodies[static_cast<std::size_t>(i + 4) % bodies.size()], 100.0, i);
    for (FlightSpec& flight : out.back().flights) flight.imu_rate_hz = i % 2 == 0 ? 1000.0 : 4000.0;
  }
  // A rotor on a body whose nominal moments are 5-20 % off (a wheel inside a body whose
  // tensor came from CAD), and the same bodies with the wheel stopped: the moments alone.
  for (int i = 0; i < per_kind; ++i) {
    const std::string& body = bodies[static_cast<std::size_t>(i) % bodies.size()];
    add("rotor_moments", "internal_momentum", body, 0.0, i, "inertia_moments");
    add("stopped", "inertia_moments", body, 0.0, i);
  }
  // Large rotors, 40-100 % of |L| (a reaction wheel idling fast in a slowly thrown body),
  // where a rotor's fit from zero stops in another minimum on about one flight in four.
  for (int i = 0; i < per_kind; ++i) {
    add("large_rotor", "internal_momentum", bodies[static_cast<std::size_t>(i + 1) % bodies.size()], 0.0, i);
    for (FlightSpec& flight : out.back().flights) {
      flight.rotor_fraction_low = 0.4;
      flight.rotor_fraction_high = 1.0;
    }
  }
  // A rotor of 15-40 % of |L| on a body whose nominal moments are also 5-20 % off, every
  // body in turn: the pair's own fit on one flight, started from the pooled fit, can stop
  // in another minimum (listed last, so every other kind keeps its seeds).
  for (int i = 0; i < per_kind; ++i) {
    const std::string& body = bodies[static_cast<std::size_t>(i) % bodies.size()];
    add("large_rotor_moments", "internal_momentum", body, 0.0, i, "inertia_moments");
    for (FlightSpec& flight : out.back().flights) {
      flight.rotor_fraction_low = 0.15;
      flight.rotor_fraction_high = 0.4;
    }
  }
  return out;
}

}  // namespace aloft::generator
