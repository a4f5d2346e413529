// A rotor together with the error it takes up (issue 31; docs/diagnose.md, "A rotor
// together with wrong moments"). Fitted alone on a body whose moments are also wrong, each
// flight's rotor takes up part of the moment error, by that flight's own rate (a moment
// error scales with w², a rotor with w), so the flights disagree on the h they share and a
// session rules the rotor out (told_apart.hpp). Forward selection finds the two only where
// the moments alone lead the first step; where the rotor outweighs the moment error,
// neither leads alone and the first step names another effect, on whose base the rotor
// still takes up the moment error.
//
// So a session also tries, at its first step, such an effect (descriptor `jointly_with`)
// fitted together with the one whose error it takes up: pooled, left out flight by flight
// and fitted on each flight alone (Candidate::flights_own_fits, its effect's part). The
// pair is a candidate of the first step only where
// - the effect alone is ruled out because its flights disagree on it;
// - the flights' own fits of the pair agree on it (kFlightsDisagree): across flights at
//   different rates a rotor and wrong moments part, so agreement there is what tells them
//   apart;
// - and the pair shrinks the held-out error of each of its effects alone by at least
//   kMinimumStepShrink, the bar a second effect meets at a step of its own.
// It is then ranked like every other candidate of the first step (named only where it
// beats the best candidate of every other effect beyond a tie); where it heads, the first
// step names both its effects.
#pragma once

#include <vector>

#include "diagnose/4_judge/analysis.hpp"
#include "diagnose/4_judge/candidate_ranking.hpp"
#include "diagnose/4_judge/candidate_evaluator.hpp"

namespace aloft::host::diagnose {

// The pairs to add to a session's first-step candidates `first` (each effect alone, not yet
// ranked; `context.own_analyses` its flights' own analyses): none for one flight.
// `pairs_only`: effects alone, fitted, that are not candidates themselves but may start a
// pair (a spun-up wheel whose steady rotor the session rules out: variant_candidates.hpp).
std::vector<Candidate> joint_candidates(const std::vector<Candidate>& first,
                                        const std::vector<Candidate>& pairs_only,
                                        const RankingContext& context, const CandidateEvaluator& evaluate);

}  // namespace aloft::host::diagnose
