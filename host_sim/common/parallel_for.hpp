// One way to spread independent work over threads, for the study's simulations and the
// diagnosis's flights. A worker's exception is carried back: the first one thrown stops
// the hand-out of further indices and is rethrown in the caller once every thread has
// joined, so an error in any flight or simulation ends the command with its one line
// rather than std::terminate. A stop asked for through common/stop_request.hpp is
// checked before each index and ends the loop the same way (Stopped).
#pragma once

#include <cstddef>
#include <functional>

namespace aloft::host {

struct ParallelProgress {
  // Called from the calling thread about every 100 ms while the work runs, and once
  // at the end with done == total; empty: no progress reports.
  std::function<void(std::size_t done, std::size_t total)> report;
};

// Runs body(i) for every i in [0, count) on up to `threads` threads (the caller's own
// thread among them when there is no progress to report). Indices are handed out one
// at a time in increasing order; which thread runs which index is not fixed, so body
// must not depend on it.
void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body,
                  const ParallelProgress& progress = {});

}  // namespace aloft::host
