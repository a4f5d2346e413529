// Variants of an effect (descriptor `variant_of`: a rotor whose speed a motor changes,
// beside the steady rotor) are tried at a step only where the effect they vary, added to
// the step's model, already fits about as well as the best of the rest: its held-out
// chi-square at most kVariantReach times the lowest of the step's candidates (the model as
// it stands among them), and it takes at least kMinimumStepShrink of the held-out gap the
// model leaves (the bar a second effect meets at a step of its own; on noise alone every
// candidate's chi-square is about the lowest). A wheel spun up after release is, to a
// steady rotor fitted to the whole flight, a rotor of the wrong size early on: the steady
// rotor still fits better than any other effect (held-back real wheel sessions: 30,156
// against 33,540 for the next), while on flights without a rotor it does not, and there the
// variant costs nothing (a flight's diagnosis would otherwise fit five more parameters, by a
// step a sample, everywhere). At the first step the model is the nominal one; at a later
// step, the effects already chosen. Beside wrong moments the wheel is also tried with them
// as a pair at the first step (its descriptor's `jointly_with`, joint_candidates.hpp), for
// which the variant is kept aside where it shrinks the steady rotor's held-out error by less
// than kMinimumStepShrink but the session rules the steady rotor out (its flights disagree
// on h): a pair only, never a candidate alone (alone, such a fit of a knock had made every
// score of its step hang on libm's last bits, 6 % apart between SSE2 and FMA). Generated
// spin-up sessions with wrong moments beside the wheel (fresh seeds): named in 0 of 3 while
// variants were tried at the first step only and dropped there, in 4 of 5 now
// (docs/validation/diagnose-accuracy.md, "A wheel beside another effect").
#pragma once

#include <functional>
#include <vector>

#include "diagnose/4_judge/analysis.hpp"
#include "diagnose/4_judge/candidate_ranking.hpp"
#include "diagnose/4_judge/candidate_evaluator.hpp"

namespace aloft::host::diagnose {

// Measured on the generated flight-controller sessions (tuning seeds): the steady rotor's
// held-out chi-square on spin-up sessions lies at 1.00 of the lowest (it is the lowest);
// 1.5 leaves room for a wheel on a body whose moments are also off.
constexpr double kVariantReach = 1.5;

// A variant tried is kept only where it shrinks its parent's held-out error by
// kMinimumStepShrink as well: on steady-rotor sessions the spin-up fitted beside the steady
// rotor took up the moments' share (the tensor's ratios read beside it 1-2 % off on 4 of
// 15 sessions, within 0.07 % beside the steady rotor), where on spin-up sessions it takes
// 17-62 % of what the steady rotor leaves (tuning seeds).
// The variants to add to a session's step: `candidates` each effect added alone to the
// model `reference` (which may be among them), judged held out, not yet ranked;
// `context.own_analyses` the flights' own analyses; `may_add` whether a variant may join
// the model (not already in it). None for one flight: a variant named only where told
// apart (a rotor) is never named there, and fitting it would cost a flight's diagnosis half
// as much again (case00: 286 -> 453 M instructions).
struct VariantCandidates {
  std::vector<Candidate> kept;       // candidates of the step
  std::vector<Candidate> for_pairs;  // first step: tried in pairs only (joint_candidates.hpp)
};
VariantCandidates variant_candidates(const std::vector<Candidate>& candidates, const Candidate& reference,
                                     const RankingContext& context, const CandidateEvaluator& evaluate,
                                     const std::function<bool(Effect)>& may_add);

}  // namespace aloft::host::diagnose
