// Turning held-out gaps into a ranking and a verdict (rules in diagnosis.hpp), shared by
// the per-flight and the pooled analysis.
#pragma once

#include <vector>

#include "diagnose/4_judge/analysis.hpp"

namespace aloft::host::diagnose {

// Held-out DA and relative error of predicted vs measured readings over the masked
// samples of every flight; accumulates into the given sums.
struct GapSums {
  double da_sq = 0.0, rel_sq = 0.0;
  double chi_square = 0.0;
  int samples = 0, residuals = 0;
  void add(const Eigen::Vector3d& predicted, const Eigen::Vector3d& measured,
           const Eigen::Vector3d& inverse_sigma);
  double rms_da_deg() const;
  double rms_rel_err() const;
};

// What the ranking needs to know about the data judged.
struct RankingContext {
  bool gyro_input = true;
  std::vector<const Flight*> flights;
  std::vector<Eigen::Vector3d> inverse_sigma;  // per flight
  double mean_speed = 0.0;                     // rad/s
  double duration_s = 0.0;                     // of the data that informs shared parameters
  const NominalInertia* nominal = nullptr;     // the stepwise selection's parameters need it
  double resolution = 0.0;                     // rad/s (noise_floor.hpp); 0: unknown
  // A session's flights, each one's own analysis (told_apart.hpp); empty for one flight.
  std::vector<const Analysis*> own_analyses;
};

// One step of the ranking: scores every candidate of `all` against the one marked
// `reference` (the model the step starts from), sorts best first, and picks the best
// physical candidate if it beats the reference by more than `margin`, with the effects
// the data cannot tell from it (score within the margin, predictions within 0.3 sigma).
// Ties (confidence.hpp): members of that class whose scores tie are named in the
// registry's order, so `best` is the first of them in the registry, not the one whose fit
// ended a bit lower; candidates outside the class that tie with it are `tied`. An effect
// named only when told apart (told_apart.hpp) and not told apart gives way to the best
// candidate of another effect (its note says why).
// Fills every evaluated candidate's score_spread, score_behind and score_behind_spread.
struct StepRanking {
  double dispersion = 1.0;
  int reference = -1;  // indices into the sorted `all`
  int best = -1;
  bool beats_reference = false;
  std::vector<Effect> equivalent;  // of `best`, itself first, the rest in registry order
  std::vector<Effect> tied;        // outside the class, in registry order
};
StepRanking rank_step(std::vector<Candidate>& all, const RankingContext& context, double margin);

// Fills score, shrink, physical, identifiable and indistinguishable; sorts best first;
// makes the verdict. `gyro_input` selects the equivalence classes that always hold.
// `inverse_sigma[f]` weighs flight f (for the indistinguishability test).
void rank_candidates(Analysis& analysis, const RankingContext& context);
void rank_candidates(Analysis& analysis, bool gyro_input, const std::vector<const Flight*>& flights,
                     const std::vector<Eigen::Vector3d>& inverse_sigma, double mean_speed, double duration_s);

}  // namespace aloft::host::diagnose
