#include "compound_effect_cases.hpp"

#include <string>

namespace aloft::generator {

std::vector<FlightCase> compound_effect_cases() {
  // Moments before axes: a compound flight turns the re-weighted tensor.
  const std::vector<std::string> classes = {"inertia_moments",  "inertia_axes", "aero_torque",
                                            "internal_damping", "impulse",      "gyro_bias",
                                            "gyro_scale"};
  const std::vector<std::string> bodies = {"box", "tilted_box", "racquet", "disc"};
  std::vector<FlightCase> cases;
  std::uint64_t seed = 20261123;
  std::size_t body = 0;
  for (std::size_t i = 0; i < classes.size(); ++i) {
    for (std::size_t j = i + 1; j < classes.size(); ++j) {
      FlightCase c;
      c.spec.data = DataKind::imu;
      c.spec.effect = classes[i];
      c.spec.second_effect = classes[j];
      c.spec.body = bodies[body++ % bodies.size()];
      if (classes[i] == "inertia_moments" && classes[j] == "gyro_scale") c.spec.body = "tilted_box";
      c.name = "compound_" + classes[i] + "+" + classes[j];
      c.seed = seed;
      seed += 0x9E3779B1ull;
      cases.push_back(c);
    }
  }
  return cases;
}

}  // namespace aloft::generator
