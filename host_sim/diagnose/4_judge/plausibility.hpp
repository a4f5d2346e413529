// Candidates whose fitted parameters make no physical sense are ruled out of the verdict,
// however well they fit: a gyro whose scale is off by more than 30 % (no phone or MEMS
// gyro is; a fit that needs it is mimicking another effect), a clock running 30 % off, and
// a model whose held-out gap is worse than the nominal model's (it explains nothing). Each
// effect's own limits are its descriptor's `senseless` (2_model/effects/<name>.cpp; the
// scale limit is kLargestSensibleScaleError there). The
// triangle inequality of fitted moments and the sign of drag are judged in the ranking.
#pragma once

#include <vector>

#include "diagnose/4_judge/analysis.hpp"

namespace aloft::host::diagnose {

// Marks such candidates not physical, with a note that says why. Call before ranking.
void rule_out_senseless(std::vector<Candidate>& candidates);

}  // namespace aloft::host::diagnose
