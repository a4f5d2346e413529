#include "diagnose/4_judge/spin_up_end.hpp"

#include <algorithm>

namespace aloft::host::diagnose {
namespace {

// Each flight's end (seconds after its first sample) and the log's rotor there.
struct FlightEnd {
  double end_s = 0.0;
  std::optional<Eigen::Vector3d> logged_h;
};

// Each flight's end to its own profile, and the longest flight's profile as the effect's
// (a fit that shares every parameter: the longest flight's end).
void set_end(EffectParameters& p, const std::vector<FlightEnd>& ends) {
  if (!p.spin_up || ends.empty()) return;
  const auto longest = std::max_element(
      ends.begin(), ends.end(), [](const FlightEnd& a, const FlightEnd& b) { return a.end_s < b.end_s; });
  p.spin_up_end_s = longest->end_s;
  p.spin_up_logged_h = longest->logged_h;
  if (p.spin_up_flights.size() != ends.size()) return;
  for (std::size_t j = 0; j < ends.size(); ++j) {
    p.spin_up_flights[j].end_s = ends[j].end_s;
    p.spin_up_flights[j].logged_h = ends[j].logged_h;
  }
  const EffectParameters::SpinUpFlight& own =
      p.spin_up_flights[static_cast<std::size_t>(longest - ends.begin())];
  p.vector = own.final_h;
  p.spin_up_profile = own.profile;
}

void set_end(Candidate& c, const std::vector<FlightEnd>& ends) {
  set_end(c.params, ends);
  for (Candidate::Alternative& a : c.alternatives) set_end(a.params, ends);
}

}  // namespace

void set_spin_up_end(Analysis& analysis, const std::vector<const Flight*>& flights) {
  std::vector<FlightEnd> ends;
  for (const Flight* f : flights) ends.push_back({f->end_s() - f->start_s(), f->logged_rotor_h_N_m_s});
  for (Candidate& c : analysis.candidates) set_end(c, ends);
  for (ModelStep& step : analysis.steps) {
    for (Candidate& c : step.candidates) set_end(c, ends);
  }
  set_end(analysis.model, ends);
  for (VerdictEffect& e : analysis.verdict.effects) set_end(e.params, ends);
  for (Note& n : analysis.notes) set_end(n.params, ends);
}

}  // namespace aloft::host::diagnose
