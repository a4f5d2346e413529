// The held-out rule of a session (judge_candidates.hpp): every effect except the impulse
// (a knock belongs to one flight) is shared by all flights, each flight keeping its own
// initial rate. Held out: leave one flight out. The effect is fitted to the other flights
// (one Gauss-Newton step from the all-flights solution, refit_from_solution.hpp); on the left-out
// flight only the initial rate is fitted, on one fold of its samples, and the gap is
// judged on the other fold (and the other way round), so that no sample is ever judged by
// a fit that saw it.
#pragma once

#include <vector>

#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/3_fit/effect_fit.hpp"
#include "diagnose/5_flow/judge_candidates.hpp"
#include "diagnose/5_flow/judged_flights.hpp"

namespace aloft::host::diagnose {

class FlightsLeftOut : public HeldOutRule {
 public:
  // `flights`: two or more; `own[j]`: flight j's own analysis (its nominal fit and its own
  // estimate of each effect); `none_all`: their nominal fits as one fit of the flights.
  // All must outlive the rule. `threads` >= 1.
  FlightsLeftOut(const JudgedFlights& flights, const std::vector<const Analysis*>& own,
                 const NominalInertia& nominal, const EffectFit& none_all, unsigned threads)
      : flights_(flights), own_(own), nominal_(nominal), none_all_(none_all), threads_(threads) {}

  // Each flight's own nominal fit and its own held-out predictions (nothing is shared, so
  // leaving a flight out changes nothing): the pooled baseline is the flights' baselines
  // put together.
  Candidate nominal_model() const override;
  // The shared parameters fitted to every flight, judged by leaving one flight out; an
  // impulse is not evaluated. An effect named only when told apart, added to a base, also
  // gets each flight's own fit of the two together (Candidate::flights_own_fits).
  Candidate evaluate(const Candidate& base, Effect added) const override;
  // A jackknife over the flights' leave-one-out fits.
  bool tensor_report(const Analysis& analysis, TensorReport& report) const override;

 private:
  EffectFit fit_pooled(Effect effect) const;
  void judge_leaving_flights_out(Candidate& c) const;
  std::vector<OwnFit> fit_each_flight(const Candidate& base, const Candidate& c) const;

  const JudgedFlights& flights_;
  const std::vector<const Analysis*>& own_;
  const NominalInertia& nominal_;
  const EffectFit& none_all_;
  unsigned threads_;
};

// A candidate of `effect` in `analysis` that was evaluated; nullptr if none.
const Candidate* evaluated_candidate(const Analysis& analysis, Effect effect);

}  // namespace aloft::host::diagnose
