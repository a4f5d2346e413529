#include "diagnose/4_judge/told_apart.hpp"

#include "diagnose/2_model/printf_text.hpp"
#include "diagnose/4_judge/between_flight_scatter.hpp"
#include "diagnose/4_judge/confidence.hpp"

namespace aloft::host::diagnose {

NotToldApart told_apart(const Candidate& head, const Candidate* rival,
                        const std::vector<const Analysis*>& own) {
  const std::string name = effect_name(head.effect);
  const std::string other = rival != nullptr ? effect_name(rival->effect) : "another effect";
  if (own.empty()) {
    return {name + " is not named from one flight: within a flight its parameters mimic " + other +
                " (docs/diagnose.md, \"A rotor inside\"); flights of one session at different rates tell "
                "them apart",
            true};
  }
  const auto scatter = between_flight_scatter(head.effect, own);
  if (scatter && scatter->chi_square_per_dof > kFlightsDisagree) {
    return {name + printf_text(": the flights' own fits scatter %.3g x beyond their uncertainty (chi-square "
                               "per degree of freedom; at most %.0f for one shared value): no one value is "
                               "shared",
                               scatter->chi_square_per_dof, kFlightsDisagree),
            false};
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
