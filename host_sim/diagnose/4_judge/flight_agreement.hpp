// Whether a session's flights agree with its pooled verdict: where most flights name one
// effect and the pool does not, which flights disagree (and where the pool agrees, which
// flights name something else). Said in a note, never changing the verdict.
#pragma once

#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/4_judge/analysis.hpp"

namespace aloft::host::diagnose {

// `own[j]`: the own analysis of `flights[j]`. Adds at most one note to `pooled`.
void note_disagreeing_flights(Analysis& pooled, const std::vector<const Flight*>& flights,
                              const std::vector<const Analysis*>& own);

}  // namespace aloft::host::diagnose
