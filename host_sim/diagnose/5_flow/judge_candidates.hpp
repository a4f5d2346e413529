// The one candidate loop of every analysis, a flight's or a session's: the nominal model,
// each candidate effect against it (in a session also the pairs of
// 4_judge/joint_candidates.hpp), the senseless ruled out, the ranking, the stepwise
// search for a compound model, the tensor report, and the confidence tempered by it. What
// differs between a flight and a session is only how a model is held out, the rule this
// loop is given:
// - one flight (folds_within_flight.hpp): fitted on each of two interleaved folds, judged
//   on the other;
// - a session (flights_left_out.hpp): effects shared by all flights, each judged on the
//   flight the fit left out.
#pragma once

#include "diagnose/4_judge/analysis.hpp"
#include "diagnose/4_judge/candidate_ranking.hpp"
#include "diagnose/4_judge/tensor_report.hpp"

namespace aloft::host::diagnose {

class HeldOutRule {
 public:
  virtual ~HeldOutRule() = default;
  // The nominal model judged held out: the reference of the first step.
  virtual Candidate nominal_model() const = 0;
  // `added` fitted jointly with the model of `base` and judged held out (the evaluator of
  // stepwise_selection.hpp).
  virtual Candidate evaluate(const Candidate& base, Effect added) const = 0;
  // The tensor report of the judged analysis (tensor_intervals.hpp); false when there is
  // none.
  virtual bool tensor_report(const Analysis& analysis, TensorReport& report) const = 0;
};

// Fills analysis.candidates, the ranking, steps, model and verdict, and the tensor report,
// every model judged by `rule`.
void judge_candidates(Analysis& analysis, const RankingContext& context, const HeldOutRule& rule);

}  // namespace aloft::host::diagnose
