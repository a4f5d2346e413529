// An added impulse's fit on one fold of the interleaved folds (3_fit/held_out.hpp): its
// time is searched again on the fold's training samples (a time is not a smooth parameter,
// and the all-data search saw the judged samples around the jump), and two things the
// search alone gets wrong are put right, each by the training samples only.
//
// The search can stop in a wrong basin: on compound_impulse+gyro_bias fold 0 it reached
// 0.3895 s at a training cost of 9.8e6, where the all-data time 0.4955 s fits the same
// samples to about 7e4 (fold 1 found it); which basin it reaches rides on its start
// rates (a start 0.3 rad/s away moved fold 1 from 0.4955 to 0.4415 s, 5.9e6). So the
// all-data solution, moved by one Gauss-Newton step on the fold's samples at the all-data
// time, is the other candidate, and the lower training cost of the two wins; the search
// keeps its time unless it is out of the window of the other minima (effect_fit.hpp).
//
// And the fold may not see the jump: where the samples on both sides of it are judged
// (the jump falls inside a judged chunk: one of the two folds of every flight with an
// impulse), the training cost is the same for every time between the fold's two nearest
// training samples. The search stops at whichever of these tied times it reaches first,
// which the last bits of its start decide, and the judged samples of the gap are
// predicted before or after the jump by that accident (compound_aero_torque+impulse,
// fold 1: training cost 50,777.7101 at every time from 0.5655 to 0.6105 s, the judged
// cost from 77,000 to 1,122,000 across them; start rates 1e-3 rad/s apart stopped the
// search at 0.5905 or 0.5755 s, the impulse's held-out error 0.025 or 0.043). The jump
// is then put in the middle of the gap: a fixed rule where the data hold no preference,
// and the one that misplaces it least in the worst case and on average (for a jump
// anywhere in the gap alike).
#pragma once

#include <cstddef>

#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/3_fit/effect_fit.hpp"
#include "diagnose/3_fit/flight_data.hpp"

namespace aloft::host::diagnose {

// The fold fit of a model whose last effect is an impulse: `searched` (its time searched
// on `train`) or one Gauss-Newton step on `train` from `all_data` (the same model fitted
// to every sample), the lower training cost as above, then with its jump in the middle of
// the gap between the training samples either side of it, refitted there by one
// Gauss-Newton step (refit_from_solution.hpp). The jump stays where a
// training sample lies next to it on either side, or where the gap reaches the flight's
// end or its settling time.
// The samples between the training samples of `train` either side of `fit`'s jump,
// [first, end): none where a training sample lies next to the jump on both sides (the
// data pin it) or where the gap reaches the flight's end.
struct SampleRange {
  std::size_t first = 0, end = 0;
};
SampleRange unseen_jump_gap(const EffectFit& fit, const FlightData& train);

// `at_all_data` (optional): `all_data` linearised at its solution for the folds to share.
EffectFit fold_impulse_fit(const EffectFit& searched, const EffectFit& all_data,
                           const NominalInertia& nominal, const FlightData& train,
                           SharedLinearisation* at_all_data = nullptr);

}  // namespace aloft::host::diagnose
