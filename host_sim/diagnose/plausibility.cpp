#include "diagnose/plausibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace aloft::host::diagnose {

void rule_out_senseless(std::vector<Candidate>& candidates) {
  const auto none = std::find_if(candidates.begin(), candidates.end(),
                                 [](const Candidate& c) { return c.effect == Effect::none && c.evaluated; });
  for (Candidate& c : candidates) {
    if (!c.evaluated || c.effect == Effect::none) continue;
    char text[160];
    Eigen::Index axis = 0;
    const double largest = c.effect == Effect::gyro_scale ? c.params.vector.cwiseAbs().maxCoeff(&axis) : 0.0;
    if (largest > kLargestSensibleScaleError) {
      std::snprintf(text, sizeof text, "ruled out: a gyro scale error of %+.0f %% is beyond any real gyro (limit %.0f %%)",
                    100.0 * c.params.vector(axis), 100.0 * kLargestSensibleScaleError);
      c.physical = false;
      c.note = text;
    } else if (c.effect == Effect::clock_drift && std::abs(c.params.rate_error) > kLargestSensibleScaleError) {
      std::snprintf(text, sizeof text, "ruled out: a clock %+.0f %% off is beyond any real clock", 100.0 * c.params.rate_error);
      c.physical = false;
      c.note = text;
    } else if (none != candidates.end() && c.heldout_rms_rel_err > none->heldout_rms_rel_err) {
      c.physical = false;
      c.note = "ruled out: its held-out gap is worse than the nominal model's";
    }
  }
}

}  // namespace aloft::host::diagnose
