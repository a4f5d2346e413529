// Which samples a fit sees and which it is judged on. Within one flight: two folds of
// interleaved chunks (even chunks train, odd chunks judge, then the other way round), so
// each held-out sample lies between trained ones and every part of the flight is judged
// once. A chunk is long enough (>= 5 samples, 1/20 of the flight) that the noise of the
// trained neighbours does not leak into it.
#pragma once

#include <array>
#include <cstddef>

#include "diagnose/3_fit/effect_fit.hpp"

namespace aloft::host::diagnose {

struct Folds {
  std::array<SampleMask, 2> train;  // train[f]: samples fold f fits on
  std::array<SampleMask, 2> judge;  // judge[f]: the complement, where fold f is judged
};

Folds interleaved_folds(std::size_t sample_count);

// The length of one chunk of the interleaved folds, in samples: max(5, n / 20). Also the
// unit over which a held-out score's spread is measured (4_judge/score_spread.hpp).
std::size_t chunk_length(std::size_t sample_count);

SampleMask all_samples(std::size_t sample_count);

// The first `fraction` of the flight (at least `minimum` samples).
SampleMask leading_samples(std::size_t sample_count, double fraction, std::size_t minimum);

}  // namespace aloft::host::diagnose
