#include "withheld_effect_cases.hpp"

#include "body_catalogue.hpp"

namespace aloft::generator {

std::vector<FlightCase> withheld_effect_cases() {
  std::vector<FlightCase> cases;
  const auto& bodies = body_names();
  const auto& effects = effect_names();
  // Seeds are spaced by a large odd constant so that neighbouring cases share nothing.
  std::uint64_t seed = 20240515;
  auto add = [&](DataKind kind, const std::string& effect, int repeats, std::size_t effect_index) {
    for (int i = 0; i < repeats; ++i) {
      FlightCase c;
      c.spec.data = kind;
      c.spec.effect = effect;
      std::size_t body = (effect_index + std::size_t(i)) % bodies.size();
      // The cylinder's body rate precesses so slowly (0.15 w_z) that a rotor of
      // 30-150 ms relaxation loses < 0.5 % of the energy in a second: no fair case.
      if (effect == "internal_damping" && bodies[body] == "cylinder") body = (body + 1) % bodies.size();
      c.spec.body = bodies[body];
      c.name = std::string(kind == DataKind::imu ? "imu_" : "markers_") + effect + "_" + std::to_string(i);
      c.seed = seed;
      seed += 0x9E3779B1ull;
      cases.push_back(c);
    }
  };
  for (std::size_t e = 0; e < effects.size(); ++e) {
    add(DataKind::imu, effects[e], effects[e] == "none" ? 6 : 5, e);
  }
  for (std::size_t e = 0; e < effects.size(); ++e) {
    if (is_sensor_effect(effects[e])) continue;
    add(DataKind::markers, effects[e], effects[e] == "none" ? 4 : 3, e + 2);
  }
  int imu_index = 0;
  for (auto& c : cases) {
    if (c.spec.data == DataKind::imu && imu_index++ % 3 == 2) c.spec.accelerometer = true;
  }
  return cases;
}

}  // namespace aloft::generator
