// A rotor spun up by a motor (effects/internal_momentum_spin_up.cpp) is reported with h at
// the end of the data it describes (SPEC §4: h_N_m_s is h at the flight's end), which its
// parameters alone do not know: the flow gives the end (a flight's duration; a session's
// longest flight's) to every fit of it in the analysis.
#pragma once

#include "diagnose/4_judge/analysis.hpp"

namespace aloft::host::diagnose {

// `end_s`: seconds after the first sample of the flight(s).
void set_spin_up_end(Analysis& analysis, double end_s);

}  // namespace aloft::host::diagnose
