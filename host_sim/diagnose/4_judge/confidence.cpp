// The two confidence judgements of confidence.hpp.
#include "diagnose/4_judge/confidence.hpp"

#include <cstdio>
#include <string>

namespace aloft::host::diagnose {

void judge_confidence(Analysis& analysis) {
  Verdict& v = analysis.verdict;
  if (v.effect == Effect::none) {
    v.confident = false;
    analysis.notes.push_back(
        "no effect stands out above the noise; a noise-only verdict is never marked confident "
        "(effects below what this flight resolves cannot be ruled out)");
    return;
  }
  const double shrink = v.heldout_rms_rel_err_before > 0
                            ? 1.0 - v.heldout_rms_rel_err_after / v.heldout_rms_rel_err_before
                            : 0.0;
  if (shrink < kConfidentShrink) {
    v.confident = false;
    v.could_not_judge.push_back("the final model leaves most of the held-out gap unexplained");
  }
}

void temper_confidence(Analysis& analysis) {
  Verdict& v = analysis.verdict;
  if (v.effect == Effect::none || v.chosen < 0) return;
  const Candidate& chosen = analysis.candidates[static_cast<std::size_t>(v.chosen)];
  char text[400];
  if (chosen.shrink < kPracticalShrink) {
    v.confident = false;
    std::snprintf(text, sizeof text,
                  "%s shrinks the held-out gap by only %.0f %% (below the %.0f %% that matters)",
                  effect_name(v.effect), 100.0 * chosen.shrink, 100.0 * kPracticalShrink);
    v.could_not_judge.push_back(text);
  }
  // A candidate ruled out for senseless parameters that explains far more than the verdict
  // says the models considered do not hold this gap: the verdict is a second best.
  for (const Candidate& c : analysis.candidates) {
    if (c.evaluated && !c.physical && c.shrink > chosen.shrink + kPracticalShrink) {
      v.confident = false;
      std::snprintf(text, sizeof text, "%s would shrink the held-out gap by %.0f %% but was ruled out (%s)",
                    effect_name(c.effect), 100.0 * c.shrink, c.note.c_str());
      v.could_not_judge.push_back(text);
      break;
    }
  }
  if (analysis.tensor && analysis.tensor->consistent_with_nominal) {
    v.confident = false;
    v.could_not_judge.push_back("the tensor report finds the nominal ratios consistent with the data");
  }
}

}  // namespace aloft::host::diagnose
