// The built-in throw as options of `aloft study`: a named preset (--throw) and the
// choices of study/synthetic_throw.hpp one by one, each overriding the preset. The
// Monte Carlo axes sampler (--axes-sampler) is here too: like the throw, the paper does
// not say it, and it applies to recordings as well.
#pragma once

#include <CLI/CLI.hpp>

#include <limits>
#include <string>

#include "study/inertia_perturbation.hpp"
#include "study/synthetic_throw.hpp"

namespace aloft::host {

struct ThrowOptions {
  static constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();
  std::string preset = "built-in";  // study/throw_presets.hpp
  double spin_rate_rev_s = kUnset;
  double spin_tilt_deg = kUnset;
  double spin_azimuth_deg = kUnset;
  double duration_s = kUnset;
  double marker_noise_mm = kUnset;
  std::string marker_layout;  // empty: the preset's
  std::string axes_sampler = "ball";

  // True when an option of the throw itself (not the sampler) was given.
  bool throw_given() const;
  // True when an option the calibration searches (or replaces) was given: --throw,
  // --spin-*, --marker-noise.
  bool searched_given() const;
};

void add_throw_options(CLI::App& command, ThrowOptions& options);

// The preset with the given options applied. Throws aloft::host::Error naming the
// option when a value is out of range or a name unknown.
SyntheticThrowSettings resolve_throw(const ThrowOptions& options);
AxesSampler resolve_axes_sampler(const ThrowOptions& options);

}  // namespace aloft::host
