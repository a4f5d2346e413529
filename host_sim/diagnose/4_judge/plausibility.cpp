#include "diagnose/4_judge/plausibility.hpp"

#include <algorithm>

#include "diagnose/2_model/effect_descriptor.hpp"

namespace aloft::host::diagnose {

void rule_out_senseless(std::vector<Candidate>& candidates) {
  const auto none = std::find_if(candidates.begin(), candidates.end(),
                                 [](const Candidate& c) { return c.effect == Effect::none && c.evaluated; });
  for (Candidate& c : candidates) {
    if (!c.evaluated || c.effect == Effect::none) continue;
    const std::string senseless = describe(c.effect).hooks.senseless(c.params);
    if (!senseless.empty()) {
      c.physical = false;
      c.note = senseless;
    } else if (none != candidates.end() && c.heldout_rms_rel_err > none->heldout_rms_rel_err) {
      c.physical = false;
      c.note = "ruled out: its held-out gap is worse than the nominal model's";
    }
  }
}

}  // namespace aloft::host::diagnose
