// A rotor spun up by a motor (effects/internal_momentum_spin_up.cpp) is reported with h at
// the end of the data it describes (SPEC §4: h_N_m_s is h at the flight's end), which its
// parameters alone do not know: the flow gives each flight's end (its duration), and the
// log's rotor there where the body file has one, to every fit of it in the analysis. A
// session's pooled fit gives each flight its own profile, and reports the longest flight's
// as the effect's.
#pragma once

#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/4_judge/analysis.hpp"

namespace aloft::host::diagnose {

// `flights`: the analysis's flights, in the order its fits hold them.
void set_spin_up_end(Analysis& analysis, const std::vector<const Flight*>& flights);

}  // namespace aloft::host::diagnose
