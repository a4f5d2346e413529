// The held-out rule of one flight (judge_candidates.hpp): every model is fitted on each of
// two interleaved folds of the flight's samples and judged on the other fold, so every
// sample is judged once, by a fit that never saw it.
#pragma once

#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/3_fit/effect_fit.hpp"
#include "diagnose/5_flow/judge_candidates.hpp"
#include "diagnose/5_flow/judged_flights.hpp"

namespace aloft::host::diagnose {

class FoldsWithinFlight : public HeldOutRule {
 public:
  // `flight`: one flight; `none_full`: the nominal model fitted to all its samples. Both
  // must outlive the rule.
  FoldsWithinFlight(const JudgedFlights& flight, const NominalInertia& nominal, const EffectFit& none_full)
      : flight_(flight), nominal_(nominal), none_full_(none_full) {}

  Candidate nominal_model() const override;
  // `added` fitted with the model of `base` on all the data (its parameters), then on each
  // fold (judged on the other): one Gauss-Newton step from the all-data solution, or a
  // refit from the base model's fold fit where an impulse's time is the fold's own.
  Candidate evaluate(const Candidate& base, Effect added) const override;
  // The fit's own covariance, widened for the residuals' serial correlation.
  bool tensor_report(const Analysis& analysis, TensorReport& report) const override;

 private:
  // Fits `c` on each fold with fit_fold(f) (kept in c.fold_fits), judges it on the other
  // fold, and records the held-out gap.
  void judge_held_out(Candidate& c, const JudgedFlights::FoldFit& fit_fold) const;

  const JudgedFlights& flight_;
  const NominalInertia& nominal_;
  const EffectFit& none_full_;
};

}  // namespace aloft::host::diagnose
