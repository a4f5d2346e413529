#include "flight_controller_cases.hpp"

#include "body_catalogue.hpp"
#include "seeded_random.hpp"

namespace aloft::generator {

FlightSpec flight_controller_spec(const std::string& effect, const std::string& body, double rate_hz,
                                  double cutoff_hz) {
  FlightSpec spec;
  spec.effect = effect;
  spec.body = body;
  spec.imu_rate_hz = rate_hz;
  spec.gyro_cutoff_hz = cutoff_hz;
  spec.gyro_filter_order = 1;
  spec.gyro_quantum_rad_s = kFlightControllerStep;
  return spec;
}

std::vector<SessionCase> flight_controller_session_cases(RotorSeeds seeds, int per_kind, int flights,
                                                         SpinUpShape shape) {
  return flight_controller_session_cases(seeds == RotorSeeds::tuning     ? 44010000ull
                                         : seeds == RotorSeeds::withheld ? 44090000ull
                                         : seeds == RotorSeeds::fresh    ? 44170000ull
                                                                         : 44250000ull,
                                         per_kind, flights, shape);
}

std::vector<SessionCase> flight_controller_session_cases(std::uint64_t first_seed, int per_kind, int flights,
                                                         SpinUpShape shape) {
  std::uint64_t seed = first_seed;
  const auto next = [&] { return seed += 0x9E3779B1ull; };
  const auto& bodies = body_names();
  const double rates[] = {1000.0, 2000.0, 4000.0, 8000.0};
  std::vector<SessionCase> out;
  const auto add = [&](const std::string& kind, const std::string& effect, int index) {
    SessionCase c;
    c.name = kind + "_" + std::to_string(index);
    c.seed = next();
    // The sensor: drawn once for the session from its seed.
    SeededRandom sensor(c.seed ^ 0x5DEECE66Dull);
    const double rate = rates[sensor.index(4)], cutoff = sensor.uniform(50.0, 250.0);
    const std::string& body = bodies[static_cast<std::size_t>(index) % bodies.size()];
    for (int f = 0; f < flights; ++f) {
      FlightSpec spec = flight_controller_spec(effect, body, rate, cutoff);
      spec.throw_seed = next();
      if (kind == "spin_up") {
        spec.rotor_spin_up = true;
        spec.rotor_fraction_low = 0.05;
        spec.rotor_fraction_high = 0.40;
        spec.spin_up_shape = shape;
      }
      c.flights.push_back(spec);
    }
    out.push_back(c);
  };
  for (int i = 0; i < per_kind; ++i) {
    add("spin_up", "internal_momentum", i);
    add("fc_moments", "inertia_moments", i);
    add("fc_misaligned", "sensor_misalignment", i);
    add("fc_stopped", "none", i);
    add("fc_impulse", "impulse", i);
  }
  return out;
}

}  // namespace aloft::generator
