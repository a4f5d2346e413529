#include "diagnose/4_judge/variant_candidates.hpp"

#include <algorithm>
#include <cmath>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/4_judge/confidence.hpp"

namespace aloft::host::diagnose {

std::vector<Candidate> variant_candidates(const std::vector<Candidate>& first, const RankingContext& context,
                                          const CandidateEvaluator& evaluate) {
  std::vector<Candidate> out;
  if (context.own_analyses.empty()) return out;
  const auto none = std::find_if(first.begin(), first.end(), [](const Candidate& c) {
    return c.effect == Effect::none && c.base.empty() && c.evaluated;
  });
  if (none == first.end()) return out;
  double lowest = INFINITY;
  for (const Candidate& c : first) {
    if (c.evaluated && c.base.empty() && std::isfinite(c.heldout_chi_square))
      lowest = std::min(lowest, c.heldout_chi_square);
  }
  for (Effect variant : registered_effects()) {
    const Effect of = describe(variant).variant_of;
    if (of == Effect::none) continue;
    const auto parent = std::find_if(first.begin(), first.end(), [of](const Candidate& c) {
      return c.effect == of && c.base.empty() && c.evaluated;
    });
    if (parent == first.end() || !(parent->heldout_chi_square <= kVariantReach * lowest) ||
        !(1.0 - parent->heldout_rms_rel_err / none->heldout_rms_rel_err >= kMinimumStepShrink))
      continue;
    // Kept where it takes what a parameter of its own must: kMinimumStepShrink of the
    // held-out gap its parent leaves (a steady rotor's flights give the variant nothing to
    // add, and its extra parameters would only take up what another effect leaves).
    Candidate c = evaluate(*none, variant);
    if (!c.evaluated || 1.0 - c.heldout_rms_rel_err / parent->heldout_rms_rel_err >= kMinimumStepShrink)
      out.push_back(std::move(c));
  }
  return out;
}

}  // namespace aloft::host::diagnose
