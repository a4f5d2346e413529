#include "diagnose/4_judge/spin_up_end.hpp"

namespace aloft::host::diagnose {
namespace {

void set_end(EffectParameters& p, double end_s) {
  if (p.spin_up) p.spin_up_end_s = end_s;
}

void set_end(Candidate& c, double end_s) {
  set_end(c.params, end_s);
  for (Candidate::Alternative& a : c.alternatives) set_end(a.params, end_s);
}

}  // namespace

void set_spin_up_end(Analysis& analysis, double end_s) {
  for (Candidate& c : analysis.candidates) set_end(c, end_s);
  for (ModelStep& step : analysis.steps) {
    for (Candidate& c : step.candidates) set_end(c, end_s);
  }
  set_end(analysis.model, end_s);
  for (VerdictEffect& e : analysis.verdict.effects) set_end(e.params, end_s);
  for (Note& n : analysis.notes) set_end(n.params, end_s);
}

}  // namespace aloft::host::diagnose
