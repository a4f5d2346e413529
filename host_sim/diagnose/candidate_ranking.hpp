// Turning held-out gaps into a ranking and a verdict (rules in diagnosis.hpp), shared by
// the per-flight and the pooled analysis.
#pragma once

#include <vector>

#include "diagnose/diagnosis.hpp"

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

// Fills score, shrink, physical, identifiable and indistinguishable; sorts best first;
// makes the verdict. `gyro_input` selects the equivalence classes that always hold.
// `inverse_sigma[f]` weighs flight f (for the indistinguishability test).
void rank_candidates(Analysis& analysis, bool gyro_input, const std::vector<const Flight*>& flights,
                     const std::vector<Eigen::Vector3d>& inverse_sigma, double mean_speed,
                     double duration_s);

}  // namespace aloft::host::diagnose
