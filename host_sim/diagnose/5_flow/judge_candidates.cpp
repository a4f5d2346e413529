#include "diagnose/5_flow/judge_candidates.hpp"

#include "diagnose/4_judge/confidence.hpp"
#include "diagnose/4_judge/joint_candidates.hpp"
#include "diagnose/4_judge/plausibility.hpp"
#include "diagnose/4_judge/stepwise_selection.hpp"
#include "diagnose/4_judge/variant_candidates.hpp"

namespace aloft::host::diagnose {

void judge_candidates(Analysis& analysis, const RankingContext& context, const HeldOutRule& rule) {
  const CandidateEvaluator evaluate = [&](const Candidate& base, Effect added) {
    return rule.evaluate(base, added);
  };
  const Candidate nominal_model = rule.nominal_model();
  for (Effect effect : candidate_effects(context.gyro_input)) {
    analysis.candidates.push_back(effect == Effect::none ? nominal_model : evaluate(nominal_model, effect));
  }
  VariantCandidates variants =
      variant_candidates(analysis.candidates, nominal_model, context, evaluate, [](Effect) { return true; });
  for (Candidate& variant : variants.kept) analysis.candidates.push_back(std::move(variant));
  for (Candidate& pair : joint_candidates(analysis.candidates, variants.for_pairs, context, evaluate))
    analysis.candidates.push_back(std::move(pair));
  rule_out_senseless(analysis.candidates);
  rank_candidates(analysis, context);
  select_stepwise(analysis, context, evaluate);
  TensorReport tensor;
  if (rule.tensor_report(analysis, tensor)) analysis.tensor = tensor;
  temper_confidence(analysis);
}

}  // namespace aloft::host::diagnose
