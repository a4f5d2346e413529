#include "diagnose/4_judge/told_apart.hpp"

#include "common/printf_text.hpp"
#include "diagnose/4_judge/between_flight_scatter.hpp"
#include "diagnose/4_judge/confidence.hpp"

namespace aloft::host::diagnose {

std::string flights_disagree_on(const Candidate& candidate, const std::vector<const Analysis*>& own) {
  const auto scatter = between_flight_scatter(candidate, own);
  if (!scatter || scatter->chi_square_per_dof <= kFlightsDisagree) return {};
  std::string on;
  for (Effect e : candidate.base) on += std::string(on.empty() ? " on " : " + ") + effect_name(e);
  return std::string(effect_name(candidate.effect)) + on +
         printf_text(
             ": the flights' own fits scatter %.3g x beyond their uncertainty (chi-square per "
             "degree of freedom; at most %.0f for one shared value), so the flights share no one value",
             scatter->chi_square_per_dof, kFlightsDisagree);
}

NotToldApart told_apart(const Candidate& head, const Candidate* rival, bool one_flight) {
  const std::string name = effect_name(head.effect);
  const std::string other = rival != nullptr ? effect_name(rival->effect) : "another effect";
  if (one_flight) {
    return {name + " is not named from one flight: within a flight its parameters can stand in for " + other +
                " (docs/diagnose.md, \"A rotor inside\"); flights of one session at different rates tell "
                "them apart",
            true};
  }
  if (rival != nullptr && scores_tie(rival->score_behind, rival->score_behind_spread)) {
    return {name + " ties with " + other +
                printf_text(" (held-out scores %.1f apart, spread %.1f)", rival->score_behind,
                            rival->score_behind_spread),
            true};
  }
  return {};
}

}  // namespace aloft::host::diagnose
