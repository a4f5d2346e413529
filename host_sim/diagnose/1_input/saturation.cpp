#include "diagnose/1_input/saturation.hpp"

#include <algorithm>
#include <cmath>

namespace aloft::host::diagnose {

Saturation mark_saturated_samples(Flight& flight) {
  Saturation out;
  const std::size_t n = flight.size();
  if (flight.usable.size() != n) flight.usable.assign(n, 1);
  std::vector<char> flat(n, 0);
  for (int a = 0; a < 3; ++a) {
    double peak = 0.0;
    for (const auto& w : flight.omega) peak = std::max(peak, std::abs(w(a)));
    if (peak <= 0.0) continue;
    std::size_t k = 0;
    while (k < n) {
      std::size_t end = k + 1;
      while (end < n && flight.omega[end](a) == flight.omega[k](a)) ++end;
      const double level = std::abs(flight.omega[k](a));
      if (end - k >= 3 && level >= 0.9 * peak) {
        for (std::size_t j = k; j < end; ++j) flat[j] = 1;
        out.level_rad_s = std::max(out.level_rad_s, level);
      }
      k = end;
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (flat[k] && flight.usable[k]) {
      flight.usable[k] = 0;
      ++out.samples;
    }
  }
  return out;
}

}  // namespace aloft::host::diagnose
