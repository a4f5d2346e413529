// How a candidate is fitted and judged held out, as the judging steps see it: the caller
// (5_flow/judge_candidates.hpp) passes the held-out rule of its data (interleaved folds for
// one flight, leave one flight out for a session), so that every step shares it.
#pragma once

#include <functional>

#include "diagnose/2_model/effect.hpp"
#include "diagnose/4_judge/analysis.hpp"

namespace aloft::host::diagnose {

// Fits `added` jointly with the model of `base` (a candidate of an earlier step, or the
// `none` candidate) and judges it held out: fills fit, params (of `added`),
// heldout_* and heldout_readings, and sets `base`/`effect`. evaluated = false when
// `added` cannot join here (e.g. an impulse shared by flights).
using CandidateEvaluator = std::function<Candidate(const Candidate& base, Effect added)>;

}  // namespace aloft::host::diagnose
