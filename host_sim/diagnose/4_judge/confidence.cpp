// The two confidence judgements of confidence.hpp.
#include "diagnose/4_judge/confidence.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "diagnose/2_model/effect_descriptor.hpp"

namespace aloft::host::diagnose {

bool scores_tie(double behind, double behind_spread) {
  return std::abs(behind) <= std::max(kTieSpreads * behind_spread, kScoreRoundingTolerance);
}

void note_close_minima(Analysis& analysis, const Candidate& chosen) {
  for (const Candidate::Alternative& a : chosen.alternatives) {
    char text[200];
    std::snprintf(text, sizeof text,
                  " fits about as well as the minimum kept (training chi-square %+.2f, within %.2f): ",
                  a.cost_behind, kCloseMinimum);
    analysis.notes.emplace_back(std::string(effect_name(chosen.effect)) + ": another minimum" + text,
                                chosen.effect, a.params);
  }
}

void note_ties(Verdict& v, const Candidate& chosen, const std::vector<Effect>& tied,
               const std::vector<Candidate>& candidates) {
  for (Effect e : tied) {
    const auto other = std::find_if(candidates.begin(), candidates.end(),
                                    [e](const Candidate& c) { return c.effect == e && c.evaluated; });
    if (other == candidates.end()) continue;
    v.confident = false;
    char text[400];
    if (!scores_tie(other->score_behind, other->score_behind_spread)) {
      // Listed although it fits better: an effect not named from this data (told_apart.hpp).
      std::snprintf(text, sizeof text,
                    "%s and %s are indistinguishable here: %s's held-out score is %.1f better (spread "
                    "%.1f), but ",
                    effect_name(chosen.effect), effect_name(e), effect_name(e), -other->score_behind,
                    other->score_behind_spread);
      v.could_not_judge.push_back(text + other->note);
      continue;
    }
    std::snprintf(text, sizeof text,
                  "%s and %s are indistinguishable here: their held-out scores differ by %.1f, within "
                  "%.0f x the spread of that difference (%.1f) or %.1f",
                  effect_name(chosen.effect), effect_name(e), std::abs(other->score_behind), kTieSpreads,
                  other->score_behind_spread, kScoreRoundingTolerance);
    v.could_not_judge.push_back(text);
  }
}

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
