// An effect whose few parameters mimic others within one flight is named only where the
// data tell it apart from them (2_model/effect_descriptor.hpp,
// `named_only_when_told_apart`). The rotor (internal_momentum): its h explains, within a
// flight, an impulse's step, a gyro bias (h = I·b to first order) and, along a body of
// revolution's axis, an axial moment change exactly (momentum_moment_equivalence.hpp);
// tried as an ordinary candidate, its h also soaked up what other effects of a compound
// flight left (docs/diagnose.md, "A rotor inside").
// What tells it apart:
// - in a session, h is one constant of the object, so the flights' own fits of it agree
//   within their errors (between_flight_scatter.hpp: chi-square per degree of freedom at
//   most kFlightsDisagree); where they do not, the ranking rules it out. An axial moment
//   change mimics h_a = dI_a w_a, which differs from flight to flight with the axial rate;
//   a knock, a bias or the racquet's own motion has no one h either. At a later step the
//   flights' own fits are of the rotor on that step's base (base effects and rotor fitted
//   per flight): a rotor fitted alone on a body whose moments are also wrong takes up part
//   of the moment error, differently by each flight's rate, and the flights would
//   disagree on h though they share one. Where that keeps the moments from leading the
//   first step, the rotor and the moments are also tried there as a pair fitted together
//   (joint_candidates.hpp);
// - and there its held-out score beats the best candidate of every other effect beyond a
//   tie (confidence.hpp, scores_tie).
// Within one flight nothing does: the other effect heads the step, and the rotor, where it
// fits as well or better, is listed as indistinguishable from it (the verdict is then not
// confident): "rotor or X, indistinguishable here".
#pragma once

#include <string>
#include <vector>

#include "diagnose/4_judge/analysis.hpp"

namespace aloft::host::diagnose {

// Why a session rules `candidate` out: the flights' own fits of its effect (on its base,
// between_flight_scatter.hpp; `own`: each flight's own analysis) scatter beyond
// kFlightsDisagree. Empty: they agree, or fewer than three flights have a fit of it.
std::string flights_disagree_on(const Candidate& candidate, const std::vector<const Analysis*>& own);

struct NotToldApart {
  std::string why;                 // empty: told apart
  bool indistinguishable = false;  // listed beside the candidate that heads in its place
};

// Whether `head` (a candidate of such an effect, every candidate's score_behind measured
// against it) is told apart from `rival` (the best eligible candidate of another effect,
// null if none) on the data of one flight (`one_flight`) or of a session.
NotToldApart told_apart(const Candidate& head, const Candidate* rival, bool one_flight);

}  // namespace aloft::host::diagnose
