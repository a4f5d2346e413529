#include "diagnose/4_judge/spin_up_end.hpp"

#include <algorithm>

namespace aloft::host::diagnose {
namespace {

// Each flight's end to its own profile, and the longest flight's profile as the effect's
// (a fit that shares every parameter: the longest flight's end).
void set_end(EffectParameters& p, const std::vector<double>& ends_s) {
  if (!p.spin_up || ends_s.empty()) return;
  const auto longest = std::max_element(ends_s.begin(), ends_s.end());
  p.spin_up_end_s = *longest;
  if (p.spin_up_flights.size() != ends_s.size()) return;
  for (std::size_t j = 0; j < ends_s.size(); ++j) p.spin_up_flights[j].end_s = ends_s[j];
  const EffectParameters::SpinUpFlight& own =
      p.spin_up_flights[static_cast<std::size_t>(longest - ends_s.begin())];
  p.vector = own.final_h;
  p.spin_up_profile = own.profile;
}

void set_end(Candidate& c, const std::vector<double>& ends_s) {
  set_end(c.params, ends_s);
  for (Candidate::Alternative& a : c.alternatives) set_end(a.params, ends_s);
}

}  // namespace

void set_spin_up_end(Analysis& analysis, const std::vector<double>& ends_s) {
  for (Candidate& c : analysis.candidates) set_end(c, ends_s);
  for (ModelStep& step : analysis.steps) {
    for (Candidate& c : step.candidates) set_end(c, ends_s);
  }
  set_end(analysis.model, ends_s);
  for (VerdictEffect& e : analysis.verdict.effects) set_end(e.params, ends_s);
  for (Note& n : analysis.notes) set_end(n.params, ends_s);
}

}  // namespace aloft::host::diagnose
