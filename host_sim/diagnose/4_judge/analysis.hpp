// What the judging makes of a flight or of a pooled session: the nominal model's gap
// (baseline, where), every candidate judged held out, the stepwise selection's steps and
// the verdict. The flow (5_flow/diagnosis.hpp) fills one per flight and one pooled.
//
// Ranking. Every candidate (none included) is fitted with the flight's initial rate and
// judged on held-out samples (3_fit/held_out.hpp); its score is the held-out chi-square (squared
// residuals over the noise floor, divided by the best candidate's chi-square per residual
// when that exceeds 1) plus kPenaltyPerParameter (confidence.hpp) for each parameter it adds. The
// verdict is the best-scoring candidate if it beats `none` by more than kVerdictMargin,
// else `none`: under noise alone the best of nine candidates gains a few units of
// chi-square by chance, never tens.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "diagnose/2_model/effect.hpp"
#include "diagnose/2_model/effect_parameters.hpp"
#include "diagnose/3_fit/effect_fit.hpp"
#include "diagnose/4_judge/invariants.hpp"
#include "diagnose/4_judge/tensor_report.hpp"

namespace aloft::host::diagnose {

struct Baseline {
  double rms_da_deg = 0.0;
  double rms_rel_err = 0.0;
};

struct TimeSlice {
  double from_s = 0.0, to_s = 0.0;
  double rms_da_deg = 0.0, rms_rel_err = 0.0;
};

struct Where {
  std::optional<double> onset_s;  // absolute time (file clock); none when never
  std::string dominant_axis = "x";
  Eigen::Vector3d rms_gap_body_rad_s = Eigen::Vector3d::Zero();  // baseline gap per body axis
  Eigen::Vector3d noise_floor = Eigen::Vector3d::Zero();         // per sensor axis
  // Readings per independent sample of that noise (NoiseFloor::correlation, > 1 behind a
  // gyro's low-pass); per flight only. A fit's covariance, its noise taken from the
  // residuals, is that many times too narrow.
  double noise_correlation = 1.0;
  double gap_over_noise = 0.0;  // baseline chi-square per residual (1: noise only)
  std::vector<TimeSlice> slices;
  std::optional<Invariants> invariants;  // per flight only
};

// One flight's own fit of an effect: its parameters and their covariance (the fit's own,
// not widened by the flight's noise correlation); empty when the fit gave none.
struct OwnFit {
  Eigen::VectorXd theta;
  Eigen::MatrixXd covariance;
};

struct Candidate {
  Effect effect = Effect::none;
  // Compound models (stepwise_selection.hpp): the effects fitted with `effect`, and
  // whether this candidate is the model its step starts from (the one to beat).
  std::vector<Effect> base;
  bool reference = false;
  EffectFit fit;  // on all the data
  EffectParameters params;
  double heldout_chi_square = 0.0;
  int heldout_residuals = 0;
  double heldout_rms_da_deg = 0.0;
  double heldout_rms_rel_err = 0.0;
  double score = 0.0;
  // The held-out score's spread (4_judge/score_spread.hpp: over the folds' chunks, in
  // score units), and how far this candidate's score lies behind its step's chosen one
  // (negative: ahead of it) with the spread of that difference.
  double score_spread = 0.0;
  double score_behind = 0.0, score_behind_spread = 0.0;
  double shrink = 0.0;                 // 1 - rel_err(with) / rel_err(none), held out
  double shrink_da = 0.0;              // the same for DA
  double reference_rms_rel_err = 0.0;  // held out, of the model this candidate is ranked against
  bool identifiable = true;
  bool physical = true;
  bool evaluated = true;  // false: not applicable here (reason in note)
  std::string note;
  std::vector<Effect> indistinguishable;  // candidates the data cannot tell from this one
  // Other minima of a searched parameter (the impulse time, the damping rotor) that fit
  // about as well as the one the search kept (confidence.hpp, kCloseMinimum): their
  // parameters and how much higher their training cost lies (negative: lower; the search
  // keeps its choice, so that the verdict does not ride on which of two it found).
  struct Alternative {
    EffectParameters params;
    double cost_behind = 0.0;
  };
  std::vector<Alternative> alternatives;
  // Session only: the effect parameters fitted without each flight (leave one flight out).
  std::vector<Eigen::VectorXd> heldout_theta;
  // Session only, an effect named only when told apart (told_apart.hpp) added to a base:
  // each flight's own fit of the base and the effect together, the effect's part (the
  // pooled flights' order). Whether the flights share one value of the effect is judged
  // on these: fitted alone, the effect would take up part of what the base explains,
  // differently in each flight (a rotor alone takes up wrong moments by each flight's rate).
  std::vector<OwnFit> flights_own_fits;
  // Held-out predictions per flight and sample (each from the fold that did not see it).
  std::vector<std::vector<Eigen::Vector3d>> heldout_readings;
  // Per flight only: the fits of the two folds (the next step starts from them).
  std::vector<EffectFit> fold_fits;
  // Per flight and sample, with an impulse only: judged by a fold that could not see on
  // which side of the jump the sample lies (3_fit/fold_impulse_time.hpp, the gap between
  // the fold's training samples either side of its jump); empty without an impulse.
  std::vector<std::vector<char>> unseen_jump;
};

// The parameters a candidate's score is penalised for: its effect's and its base's
// (effect_penalty_count; the nominal model, `none`, has none).
inline int penalty_count(const Candidate& c) {
  int parameters = effect_penalty_count(c.effect);
  for (Effect e : c.base) parameters += effect_penalty_count(e);
  return parameters;
}

// One effect of the final model (SPEC §4 verdict.effects).
struct VerdictEffect {
  Effect effect = Effect::none;
  std::vector<Effect> equivalent;
  std::vector<Effect> indistinguishable;   // ties outside the class at its step (ModelStep)
  EffectParameters params;                 // from the final model's fit
  int step = 0;                            // the step it joined at (1: first)
  double heldout_rms_rel_err_after = 0.0;  // of the model as it stood after that step
  double heldout_rms_da_after_deg = 0.0;
  double step_shrink = 0.0;  // 1 - rel_err(after its step) / rel_err(before)
  double shrink = 0.0;       // 1 - rel_err(final model) / rel_err(final model without it)
};

// One step of the stepwise selection: the model it starts from, every candidate
// addition judged held out, and what was added (nothing: the selection stopped).
struct ModelStep {
  std::vector<Effect> model;          // effects before the step
  std::vector<Candidate> candidates;  // best first; the reference is the starting model
  int added = -1;                     // index into candidates, -1: nothing joined
  std::vector<Effect> equivalent;     // the added effect's class at this step
  // Additions outside that class whose score ties with it (confidence.hpp, ties).
  std::vector<Effect> indistinguishable;
  double dispersion = 1.0;
  double heldout_rms_rel_err_before = 0.0, heldout_rms_rel_err_after = 0.0;
  double heldout_rms_da_before_deg = 0.0, heldout_rms_da_after_deg = 0.0;
  double shrink = 0.0;  // 1 - after / before (relative error)
};

struct Verdict {
  Effect effect = Effect::none;
  std::vector<Effect> equivalent;
  // Candidates outside the class whose held-out score ties with the verdict's
  // (confidence.hpp, ties): the data cannot choose between them, so not confident.
  std::vector<Effect> indistinguishable;
  int chosen = -1;  // index into Analysis::candidates
  double heldout_rms_da_before_deg = 0.0, heldout_rms_da_after_deg = 0.0;
  double heldout_rms_rel_err_before = 0.0, heldout_rms_rel_err_after = 0.0;
  bool confident = true;
  std::vector<std::string> could_not_judge;
  // The final model, most important first (empty when the verdict is none).
  std::vector<VerdictEffect> effects;
};

// A note for the reader. Most are worded where they are judged; one that names a fitted
// effect's parameters (another minimum of the chosen fit) carries them, and the report
// appends them in its own words (6_report/effect_words.hpp), so judging needs none.
struct Note {
  Note(std::string words) : text(std::move(words)) {}
  Note(const char* words) : text(words) {}
  Note(std::string words, Effect effect, EffectParameters params)
      : text(std::move(words)), params_of(effect), params(std::move(params)) {}
  std::string text;
  std::optional<Effect> params_of;  // whose `params` follow the text, if any
  EffectParameters params;
};

struct Analysis {
  Baseline baseline;
  std::optional<TensorReport> tensor;  // SPEC §4 `tensor` (tensor_report.hpp)
  Where where;
  std::vector<Candidate> candidates;  // best first
  Verdict verdict;
  // The best candidate's held-out chi-square per residual, floored at 1: how much of the
  // gap no candidate explains (scores are divided by it; see candidate_ranking.cpp).
  double dispersion = 1.0;
  std::vector<Note> notes;
  // The stepwise selection (steps[0] is the single-effect step, whose candidates are
  // `candidates` above), and the final model it settled on (effect none: nothing joined).
  std::vector<ModelStep> steps;
  Candidate model;
};

// The first step's pair (joint_candidates.hpp: an effect fitted together with the one
// whose error it takes up) where it joined the model there and holds `effect`, in its
// base or as its effect: its index in `candidates`; else -1.
inline int first_step_pair_holding(const Analysis& a, Effect effect) {
  const int first = a.steps.empty() ? -1 : a.steps.front().added;
  if (first < 0) return -1;
  const Candidate& joined = a.candidates[static_cast<std::size_t>(first)];
  const bool holds = joined.effect == effect ||
                     std::find(joined.base.begin(), joined.base.end(), effect) != joined.base.end();
  return !joined.base.empty() && holds ? first : -1;
}
}  // namespace aloft::host::diagnose
