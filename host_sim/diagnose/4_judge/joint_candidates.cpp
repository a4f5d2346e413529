#include "diagnose/4_judge/joint_candidates.hpp"

#include <algorithm>
#include <optional>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/4_judge/between_flight_scatter.hpp"
#include "diagnose/4_judge/confidence.hpp"

namespace aloft::host::diagnose {
namespace {

// The candidate of `effect` alone (a fit of it to every flight), judged held out or not:
// leaving a flight out of the moments alone can diverge where a rotor outweighs the
// moment error (one withheld racquet session of ten), and its fit still starts the pair's.
const Candidate* alone_of(const std::vector<Candidate>& first, Effect effect) {
  const auto it = std::find_if(first.begin(), first.end(), [effect](const Candidate& c) {
    return c.effect == effect && c.base.empty() && c.fit.theta.size() > 0 && c.fit.theta.allFinite();
  });
  return it != first.end() ? &*it : nullptr;
}

// The flights' own fits of c's effect (on c's base) scatter beyond their errors (yes),
// agree within them (no), or fewer than three flights have one (nullopt).
std::optional<bool> flights_disagree(const Candidate& c, const std::vector<const Analysis*>& own) {
  const auto scatter = between_flight_scatter(c, own);
  if (!scatter) return std::nullopt;
  return scatter->chi_square_per_dof > kFlightsDisagree;
}

// The pair shrinks the held-out error of `alone` (one of its effects alone; the nominal
// model's, `none`, where that one could not be judged held out) by at least the stepwise
// selection's bar, kMinimumStepShrink: each effect takes a visible share of what the other
// leaves, as it would have to at a step of its own. Measured on the tuning seeds: the rotor
// with wrong moments shrinks the moments' error by 0.87 to 0.998 and the rotor's by 0.97 to
// 0.995; with the wheel stopped, and on wrong moments of a body of revolution, the pair
// shrinks the moments' error by 0.000 to -0.001.
bool takes_a_share_of(const Candidate& pair, const Candidate& alone, const Candidate& none) {
  const double before = alone.evaluated ? alone.heldout_rms_rel_err : none.heldout_rms_rel_err;
  return before > 0.0 && 1.0 - pair.heldout_rms_rel_err / before >= kMinimumStepShrink;
}

}  // namespace

std::vector<Candidate> joint_candidates(const std::vector<Candidate>& first,
                                        const std::vector<Candidate>& pairs_only,
                                        const RankingContext& context, const CandidateEvaluator& evaluate) {
  std::vector<Candidate> out;
  const auto none = std::find_if(first.begin(), first.end(), [](const Candidate& c) {
    return c.effect == Effect::none && c.base.empty() && c.evaluated;
  });
  if (context.own_analyses.empty() || none == first.end()) return out;
  const auto try_pair = [&](const Candidate& alone) {
    const Effect jointly_with = describe(alone.effect).jointly_with;
    if (!alone.evaluated || !alone.base.empty() || jointly_with == Effect::none) return;
    const Candidate* with = alone_of(first, jointly_with);
    if (with == nullptr || flights_disagree(alone, context.own_analyses) != true) return;
    Candidate pair = evaluate(*with, alone.effect);
    if (pair.evaluated && flights_disagree(pair, context.own_analyses) == false &&
        takes_a_share_of(pair, alone, *none) && takes_a_share_of(pair, *with, *none))
      out.push_back(std::move(pair));
  };
  for (const Candidate& alone : first) try_pair(alone);
  for (const Candidate& alone : pairs_only) try_pair(alone);
  return out;
}

}  // namespace aloft::host::diagnose
