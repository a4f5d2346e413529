// Every threshold that decides a verdict and its confidence, in one place, each with the
// measurement that set it (or, where none was recorded, the commit that chose it and the
// closest case measured since). Who applies them: the ranking (candidate_ranking.hpp:
// penalty, margin), the stepwise selection (stepwise_selection.hpp: step shrink), the
// practical bar (practical_significance.hpp: resolution, smallest shrink), and the two
// functions below (confident shrink, practical shrink). Per-effect bars stay in each
// effect's descriptor (2_model/effects/<name>.cpp: `too_small`, `senseless`, `tolerance`).
//
// A change here moves verdicts: re-run the withheld, compound, phone and session figures
// of the diagnose tests and tests/diagnose/make_reports.sh on the shared data.
#pragma once

#include <cstddef>

#include "diagnose/4_judge/analysis.hpp"

namespace aloft::host::diagnose {

// Fewer usable samples than this cannot inform an initial rate and an effect with
// residuals left to judge them: the verdict is not confident and the command refuses a
// single flight. Chosen with the first diagnosis (3950330); no measurement recorded.
constexpr std::size_t kMinimumSamples = 20;

// Score = held-out chi-square (over the dispersion) + kPenaltyPerParameter per
// parameter; the verdict must beat `none` (and a step the standing model) by
// kVerdictMargin. Chosen with the first diagnosis (3950330): under noise alone the best of
// nine candidates gains a few units of chi-square by chance, never tens; the noise-only
// flights of tests/diagnose/test_withheld_effects.cpp measure it (it prints "none on N of
// M noise-only flights").
constexpr double kPenaltyPerParameter = 4.0;
constexpr double kVerdictMargin = 25.0;

// Ties (candidate_ranking.cpp, rank_step). Two candidates whose held-out scores differ by
// no more than kTieSpreads times the spread of that difference (score_spread.hpp: the
// chunk-by-chunk differences of their held-out chi-square) are indistinguishable: both are
// named, the verdict is not confident, and the report says why. k = 2: a difference
// within two standard errors is one a two-sided test at about 5 % cannot tell from zero
// (the chunks' differences are close to normal once summed over ~20 chunks).
constexpr double kTieSpreads = 2.0;
// Scores closer than this are equal whatever their spread: two fits of one class (e.g.
// inertia_axes and sensor_misalignment from a gyro, the same predictions) differ only by
// where each fit stopped and by the last bits of libm's sin/exp/pow, which glibc picks by
// CPU. Measured: the largest difference of a candidate's score between the SSE2 and the
// FMA/AVX2 libm (GLIBC_TUNABLES, tests/diagnose/same_verdict_every_cpu.sh) on the 70
// withheld-effect flights; see docs/diagnose.md, "The same verdict on every CPU".
constexpr double kScoreRoundingTolerance = 1.0;
// Searches over a parameter with several minima (3_fit/start_search.cpp: the impulse time,
// scanned over the whole flight and refined round the best two peaks; the damping rotor,
// from a grid of 12 starts) keep the best, and report another minimum whose training
// chi-square (over the fit's dispersion) lies within kCloseMinimum of it: 3.84 is the 95 %
// point of chi-square with one degree of freedom, so each lies inside the other's 95 %
// likelihood interval for the one searched parameter.
constexpr double kCloseMinimum = 3.84;
// Two minima whose costs agree within kSameMinimum are one: the same predictions reached
// by parameters the data do not pin (a rotor too loose to turn with the body, whose size
// then wanders); `identifiable` reports those. On the 70 withheld flights such pairs of
// damping fits differ by 1e-11 to 1e-5, distinct minima by 0.01 or more.
constexpr double kSameMinimum = 1e-3;

// Whether a score `behind` another by this much (either sign), with this spread of the
// difference, ties with it.
bool scores_tie(double behind, double behind_spread);
// Within an equivalence class, tied members are named in one fixed order, the registry's
// (2_model/effects/effect_list.def), whatever fit ended a bit lower; a candidate outside
// the class within kScoreRoundingTolerance heads the verdict by the same order.
// A verdict whose chosen candidate ties with ones outside its class (`tied`, found among
// `candidates`) is not confident, one line each in could_not_judge.
// A note for each close other minimum of the chosen candidate's search (kCloseMinimum).
void note_close_minima(Analysis& analysis, const Candidate& chosen);
void note_ties(Verdict& v, const Candidate& chosen, const std::vector<Effect>& tied,
               const std::vector<Candidate>& candidates);

// A stepwise addition must shrink the held-out relative error by at least this: a real
// second cause takes a visible share of what is left, a model's small misfit of the first
// does not. Chosen with the stepwise selection (3086d66); the closest measured case since
// is the racquet's first session, whose internal_damping joins at 17.4 % (README, racquet
// table; tests/diagnose/test_racquet_sessions.cpp).
constexpr double kMinimumStepShrink = 0.15;

// The practical bar (practical_significance.hpp). A held-out gap below kResolutionMultiple
// times the data's resolution holds nothing the sensor resolves (chosen in 1259fd7; no
// measurement recorded). An effect that closes less than
// kSmallestShrink of the gap is none: the noise-only phone session's 0.3 % gyro scale
// closes 0.5 %, the weakest right verdict of the withheld tests 1.1 % (drag from
// marker-derived rates), and a 2 % bar lost that case (ffcbd55: withheld 67/70,
// compound 19/21, phone 59/62, sessions 7/7).
constexpr double kResolutionMultiple = 2.0;
constexpr double kSmallestShrink = 0.01;

// A verdict is confident only if it names an effect, every parameter it reports is pinned
// (identifiable; rank_candidates and select_stepwise clear `confident` otherwise) and the
// final model takes at least kConfidentShrink of the held-out gap. Never for `none`.
// Chosen in 1259fd7, where the withheld-effect tests began to count how often confident
// verdicts are right (test_withheld_effects.cpp prints the count).
constexpr double kConfidentShrink = 0.3;
void judge_confidence(Analysis& analysis);

// A verdict is not confident when its chosen candidate shrinks the held-out gap by less
// than kPracticalShrink, when a candidate ruled out as senseless would shrink it by
// kPracticalShrink more, or when the tensor report (if any) finds the nominal ratios
// consistent with the data. Chosen in f1a39cd with the tensor report; no measurement
// recorded.
constexpr double kPracticalShrink = 0.10;
void temper_confidence(Analysis& analysis);

}  // namespace aloft::host::diagnose
