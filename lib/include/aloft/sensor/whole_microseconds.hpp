// Whole microseconds (the 64-bit stamps and durations of aloft/sensor/imu_sample.hpp) to and from
// Scalar, through 32 bits. A single-precision FPU (Cortex-M4F) converts between float and
// 32-bit integers in one instruction, but libgcc converts float to and from 64-bit
// integers in software, through soft double arithmetic: tens of instructions per sample
// and kilobytes of flash. The results are those of the direct 64-bit conversions for every
// value the detector meets (durations of a few milliseconds).
#pragma once

#include <cstdint>

namespace aloft {

// A duration (µs) as Scalar: up to 2^32 - 1 µs (71 minutes) the same value as
// static_cast<Scalar>(us); beyond, the two halves are converted apart (rounded twice, so
// off by at most one unit in the last place: a gap that long is a gap either way).
template <typename Scalar>
inline Scalar scalar_of_us(std::uint64_t us) {
  const auto low = static_cast<Scalar>(static_cast<std::uint32_t>(us));
  if (us <= 0xFFFFFFFFu) return low;
  return static_cast<Scalar>(static_cast<std::uint32_t>(us >> 32)) * Scalar(4294967296.0) + low;
}

// A nonnegative duration (µs) truncated to whole µs, as static_cast<std::uint64_t>(us)
// would; at most 2^32 - 1 (71 minutes), and 0 for a negative or NaN one.
template <typename Scalar>
inline std::uint64_t whole_us(Scalar us) {
  if (!(us > Scalar(0))) return 0;
  return us < Scalar(4294967296.0) ? static_cast<std::uint32_t>(us) : 0xFFFFFFFFu;
}

}  // namespace aloft
