#include "study/throw_presets.hpp"

#include "common/commands.hpp"

namespace aloft::host {

SyntheticThrowSettings throw_preset(const std::string& name) {
  SyntheticThrowSettings s;
  if (name == "built-in") return s;
  // Found by `aloft study --calibrate-to-paper` (seed 1, default layout and sampler):
  // the throw whose GF and CP rows in that frame come closest to the paper's.
  if (name == "paper-body") {
    s.spin_rate_rev_s = 2.71875;
    s.spin_tilt_deg = 58.0;
    s.spin_azimuth_deg = 60.0;
    s.marker_noise_m = 0.125e-3;
    return s;
  }
  if (name == "paper-world") {
    s.spin_rate_rev_s = 1.375;
    s.spin_tilt_deg = 84.0;
    s.spin_azimuth_deg = 45.0;
    s.marker_noise_m = 0.08e-3;
    return s;
  }
  throw Error("study: --throw must be built-in, paper-body or paper-world, not '" + name + "'");
}

}  // namespace aloft::host
