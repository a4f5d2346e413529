#include "diagnose/3_fit/held_out.hpp"

#include <algorithm>

namespace aloft::host::diagnose {

std::size_t chunk_length(std::size_t sample_count) { return std::max<std::size_t>(5, sample_count / 20); }

Folds interleaved_folds(std::size_t sample_count) {
  const std::size_t chunk = chunk_length(sample_count);
  Folds folds;
  for (int f = 0; f < 2; ++f) {
    folds.train[f].assign(sample_count, 0);
    folds.judge[f].assign(sample_count, 0);
  }
  for (std::size_t k = 0; k < sample_count; ++k) {
    const bool even = (k / chunk) % 2 == 0;
    folds.train[0][k] = even;
    folds.judge[0][k] = !even;
    folds.train[1][k] = !even;
    folds.judge[1][k] = even;
  }
  return folds;
}

SampleMask all_samples(std::size_t sample_count) { return SampleMask(sample_count, 1); }

SampleMask leading_samples(std::size_t sample_count, double fraction, std::size_t minimum) {
  const std::size_t count =
      std::min(sample_count,
               std::max(minimum, static_cast<std::size_t>(fraction * static_cast<double>(sample_count))));
  SampleMask mask(sample_count, 0);
  std::fill(mask.begin(), mask.begin() + static_cast<std::ptrdiff_t>(count), 1);
  return mask;
}

}  // namespace aloft::host::diagnose
