#include "phone_like_cases.hpp"

#include "body_catalogue.hpp"

namespace aloft::generator {

std::vector<FlightCase> phone_like_flight_cases() {
  std::vector<FlightCase> cases;
  const auto& bodies = body_names();
  const auto& effects = effect_names();
  std::uint64_t seed = 20261124;
  for (std::size_t e = 0; e < effects.size(); ++e) {
    const int repeats = effects[e] == "none" ? 8 : 6;
    for (int i = 0; i < repeats; ++i) {
      FlightCase c;
      c.spec.effect = effects[e];
      std::size_t body = (e + std::size_t(i)) % bodies.size();
      if (effects[e] == "internal_damping" && bodies[body] == "cylinder") body = (body + 1) % bodies.size();
      c.spec.body = bodies[body];
      c.name = "phone_" + effects[e] + "_" + std::to_string(i);
      c.seed = seed;
      seed += 0x9E3779B1ull;
      cases.push_back(c);
    }
  }
  return cases;
}

std::vector<PhoneSessionCase> phone_like_session_cases() {
  const char* effects[] = {"none",       "inertia_moments",     "inertia_axes", "gyro_bias",
                           "gyro_scale", "sensor_misalignment", "clock_drift"};
  const auto& bodies = body_names();
  std::vector<PhoneSessionCase> cases;
  std::uint64_t seed = 20261125;
  for (std::size_t i = 0; i < 7; ++i) {
    PhoneSessionCase c;
    c.flight.spec.effect = effects[i];
    c.flight.spec.body = bodies[i % bodies.size()];
    c.flight.name = std::string("session_") + effects[i];
    c.flight.seed = seed;
    seed += 0x9E3779B1ull;
    cases.push_back(c);
  }
  return cases;
}

}  // namespace aloft::generator
