// Lanes: the core's hot kernels (aloft/dynamics/principal_dynamics.hpp, aloft/lanes/lane_angle.hpp) are
// written once over a "lane type" T, which is either a plain float or double (one
// simulation) or a SIMD register holding several of them (several simulations side by
// side, aloft/lanes/xsimd_lanes.hpp). A lane type needs +, -, *, /, sqrt, comparisons and
// select(mask, a, b) and any(mask); for plain scalars they are defined below, for SIMD types it is
// found by argument-dependent lookup in the SIMD library's namespace.
#pragma once

#include <type_traits>

namespace aloft {

// What a lane type holds: its scalar (float or double) and how many lanes it has.
// aloft/lanes/xsimd_lanes.hpp specialises it for SIMD registers.
template <typename T, typename Enable = void>
struct LaneTraits;
template <typename T>
struct LaneTraits<T, std::enable_if_t<std::is_floating_point<T>::value>> {
  using Scalar = T;
  static constexpr int count = 1;
  static T load(const Scalar* p) { return *p; }  // count consecutive scalars
  static void store(const T& v, Scalar* p) { *p = v; }
};

template <typename T>
using LaneScalar = typename LaneTraits<T>::Scalar;

// A vector and a Hamilton quaternion (w + x i + y j + z k) of lane type T: component by
// component, so that lane l of every component is simulation l.
template <typename T>
struct LaneVec3 {
  T x, y, z;
};
template <typename T>
struct LaneQuat {
  T w, x, y, z;
};

// Lane-wise choice: mask ? a : b (a plain scalar has one lane).
template <typename T, std::enable_if_t<std::is_floating_point<T>::value, int> = 0>
inline T select(bool mask, T a, T b) {
  return mask ? a : b;
}

// Whether any lane of a mask is set (xsimd::any for SIMD masks).
inline bool any(bool mask) { return mask; }

}  // namespace aloft
