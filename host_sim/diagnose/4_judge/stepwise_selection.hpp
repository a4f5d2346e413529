// Compound gaps (SPEC §4 `verdict.effects`): forward stepwise selection. Starting from
// the single-effect verdict (candidate_ranking.hpp, step 1; in a session that step may
// name a pair fitted together, joint_candidates.hpp, and then names both), each further step fits
// every remaining effect jointly with the effects already in the model and judges the
// result held out; the best addition joins only if it beats the model as it stands by
// more than kVerdictMargin plus its parameters' penalty (the same rule as step 1, with
// the standing model in place of `none`) and shrinks the held-out relative error by at
// least kMinimumStepShrink (a practical bar: a real second cause takes a visible share of
// what is left, a model's small misfit of the first does not). Equivalence classes are
// found within each step.
//
// The selection does not know how candidates are fitted or held out: the caller passes
// an evaluator (the held-out rule of 5_flow/judge_candidates.hpp: interleaved folds for
// one flight, leave one flight out for a session), so both share one implementation of
// the rule.
#pragma once

#include <functional>

#include "diagnose/4_judge/candidate_ranking.hpp"
#include "diagnose/4_judge/confidence.hpp"
#include "diagnose/4_judge/analysis.hpp"
#include "diagnose/4_judge/candidate_evaluator.hpp"

namespace aloft::host::diagnose {

// At most this many effects in the final model.
constexpr int kMaximumEffects = 3;
// A step must shrink the held-out relative error by at least kMinimumStepShrink
// (confidence.hpp).

// Runs the steps after `analysis` holds its ranked single-effect candidates and verdict
// (rank_candidates), and fills analysis.steps, analysis.model and verdict.effects,
// verdict.heldout_*_after (the final model's). verdict.effect becomes the most important
// effect of the final model.
// The first step's winner must also matter (practical_significance.hpp), else the
// verdict is `none`. Ends with judge_confidence (confidence.hpp).
void select_stepwise(Analysis& analysis, const RankingContext& context, const CandidateEvaluator& evaluate);

}  // namespace aloft::host::diagnose
