#include "diagnose/4_judge/variant_candidates.hpp"

#include <algorithm>
#include <cmath>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/4_judge/confidence.hpp"
#include "diagnose/4_judge/told_apart.hpp"

namespace aloft::host::diagnose {

VariantCandidates variant_candidates(const std::vector<Candidate>& candidates, const Candidate& reference,
                                     const RankingContext& context, const CandidateEvaluator& evaluate,
                                     const std::function<bool(Effect)>& may_add) {
  VariantCandidates out;
  if (context.own_analyses.empty() || !reference.evaluated) return out;
  double lowest = reference.heldout_chi_square;
  for (const Candidate& c : candidates) {
    if (c.evaluated && std::isfinite(c.heldout_chi_square)) lowest = std::min(lowest, c.heldout_chi_square);
  }
  for (Effect variant : registered_effects()) {
    const Effect of = describe(variant).variant_of;
    if (of == Effect::none || !may_add(variant)) continue;
    const auto parent = std::find_if(candidates.begin(), candidates.end(), [&](const Candidate& c) {
      return c.effect == of && c.evaluated && &c != &reference;
    });
    if (parent == candidates.end() || !(parent->heldout_chi_square <= kVariantReach * lowest) ||
        !(1.0 - parent->heldout_rms_rel_err / reference.heldout_rms_rel_err >= kMinimumStepShrink))
      continue;
    // Kept where it takes what a parameter of its own must: kMinimumStepShrink of the
    // held-out gap its parent leaves (a steady rotor's flights give the variant nothing to
    // add, and its extra parameters would only take up what another effect leaves). Else,
    // where the session rules its parent out (its flights' own fits of it disagree), it
    // may still start a pair.
    Candidate c = evaluate(reference, variant);
    if (!c.evaluated || 1.0 - c.heldout_rms_rel_err / parent->heldout_rms_rel_err >= kMinimumStepShrink)
      out.kept.push_back(std::move(c));
    else if (!flights_disagree_on(*parent, context.own_analyses).empty())
      out.for_pairs.push_back(std::move(c));
  }
  return out;
}

}  // namespace aloft::host::diagnose
