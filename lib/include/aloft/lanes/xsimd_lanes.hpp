// SIMD registers as lane types (aloft/lanes/lanes.hpp) through xsimd: an xsimd::batch<S, A>
// holds size() simulations of scalar S side by side, and the core's lane kernels
// (aloft/dynamics/principal_dynamics.hpp, aloft/lanes/lane_angle.hpp) run on it unchanged; xsimd's own
// select, abs and sqrt are found by argument-dependent lookup. Host only: the Cortex-M4F
// has no SIMD floating point, and there the same kernels run on plain float.
// Why xsimd: docs/accuracy-and-speed.md, "Speed of the core".
#pragma once

#include <xsimd/xsimd.hpp>

#include "aloft/lanes/lanes.hpp"

namespace aloft {

template <typename S, typename A>
struct LaneTraits<xsimd::batch<S, A>, void> {
  using Scalar = S;
  static constexpr int count = static_cast<int>(xsimd::batch<S, A>::size);
  static xsimd::batch<S, A> load(const S* p) { return xsimd::batch<S, A>::load_unaligned(p); }
  static void store(const xsimd::batch<S, A>& v, S* p) { v.store_unaligned(p); }
};

}  // namespace aloft
