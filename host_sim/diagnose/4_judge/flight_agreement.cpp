#include "diagnose/4_judge/flight_agreement.hpp"

#include <algorithm>
#include <string>

namespace aloft::host::diagnose {

void note_disagreeing_flights(Analysis& pooled, const std::vector<const Flight*>& flights,
                              const std::vector<const Analysis*>& own) {
  std::vector<Effect> named;
  for (const Analysis* a : own) named.push_back(a->verdict.effect);
  Effect majority = Effect::none;
  std::size_t most = 0;
  for (Effect e : named) {
    const std::size_t votes = static_cast<std::size_t>(std::count(named.begin(), named.end(), e));
    if (votes > most) {
      most = votes;
      majority = e;
    }
  }
  const std::vector<Effect>& same = pooled.verdict.equivalent;
  const bool pool_agrees = std::find(same.begin(), same.end(), majority) != same.end();
  std::string names;
  for (std::size_t j = 0; j < flights.size(); ++j) {
    const Effect said = own[j]->verdict.effect;
    if (std::find(same.begin(), same.end(), said) != same.end()) continue;
    names += (names.empty() ? "" : ", ") + flights[j]->name + " (" + effect_name(said) + ")";
  }
  if (names.empty()) return;
  if (!pool_agrees && 2 * most > named.size()) {
    pooled.notes.push_back(std::to_string(most) + " of " + std::to_string(named.size()) + " flights name " +
                           effect_name(majority) +
                           " but the pool does not; flights that disagree with the pool: " + names);
  } else {
    pooled.notes.push_back("flights whose own verdict differs from the pool's: " + names);
  }
}

}  // namespace aloft::host::diagnose
