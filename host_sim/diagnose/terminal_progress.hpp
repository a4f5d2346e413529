// Progress of a long session on a terminal: a session of hundreds of flights runs for
// minutes, and without a word it cannot be told from a hang. One line on stderr,
// rewritten in place ("diagnose: 12 / 60 flights, about 40 s left"), and nothing at all
// when stderr is not a terminal (a log file, a job scheduler, a test).
#pragma once

#include "common/parallel_for.hpp"

namespace aloft::host::diagnose {

// The reporter for diagnose_session's flights; empty when stderr is not a terminal.
ParallelProgress terminal_flight_progress();

// Clears the progress line, if one was written.
void clear_terminal_progress();

}  // namespace aloft::host::diagnose
