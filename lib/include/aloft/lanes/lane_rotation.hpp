// ω from consecutive orientations, lane-wise (aloft/lanes/lanes.hpp), for simulations that
// compare a simulated rate with a measured one sample by sample.
//
// The rotation from orientation a to orientation b has the axis of a^-1 b, in a's (body)
// axes, and of b a^-1, in world axes. A deviation angle needs only that direction, so
// these return the vector part of the relative quaternion on its short side (w >= 0):
// the axis scaled by sin(angle/2), which points along log(...) = omega dt
// (aloft/dynamics/angular_velocity.hpp), without the log's atan2 and division. `direction` (+1 or
// -1 per lane) reverses the axis for a step taken backward in time, where the state
// before the step is the later orientation: vec(b^-1 a) = -vec(a^-1 b) exactly.
#pragma once

#include "aloft/lanes/lanes.hpp"

namespace aloft {

// vec(a^-1 b) on the short side, times direction: the rate axis in a's axes.
template <typename T>
inline LaneVec3<T> lane_body_rotation_axis(const LaneQuat<T>& a, const LaneQuat<T>& b, const T& direction) {
  const T w = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
  const T s = select(w < T(LaneScalar<T>(0)), -direction, direction);
  return {s * (a.w * b.x - b.w * a.x - (a.y * b.z - a.z * b.y)),
          s * (a.w * b.y - b.w * a.y - (a.z * b.x - a.x * b.z)),
          s * (a.w * b.z - b.w * a.z - (a.x * b.y - a.y * b.x))};
}

// vec(b a^-1) on the short side, times direction: the rate axis in world axes.
template <typename T>
inline LaneVec3<T> lane_world_rotation_axis(const LaneQuat<T>& a, const LaneQuat<T>& b, const T& direction) {
  const T w = a.w * b.w + a.x * b.x + a.y * b.y + a.z * b.z;
  const T s = select(w < T(LaneScalar<T>(0)), -direction, direction);
  return {s * (a.w * b.x - b.w * a.x + (a.y * b.z - a.z * b.y)),
          s * (a.w * b.y - b.w * a.y + (a.z * b.x - a.x * b.z)),
          s * (a.w * b.z - b.w * a.z + (a.x * b.y - a.y * b.x))};
}

// A 3x3 matrix of lane type T (row-major), one per lane: R v and R^T v.
template <typename T>
struct LaneMat3 {
  T m[3][3];
};

template <typename T>
inline LaneVec3<T> lane_rotate(const LaneMat3<T>& r, const LaneVec3<T>& v) {
  return {r.m[0][0] * v.x + r.m[0][1] * v.y + r.m[0][2] * v.z,
          r.m[1][0] * v.x + r.m[1][1] * v.y + r.m[1][2] * v.z,
          r.m[2][0] * v.x + r.m[2][1] * v.y + r.m[2][2] * v.z};
}

template <typename T>
inline LaneVec3<T> lane_rotate_transposed(const LaneMat3<T>& r, const LaneVec3<T>& v) {
  return {r.m[0][0] * v.x + r.m[1][0] * v.y + r.m[2][0] * v.z,
          r.m[0][1] * v.x + r.m[1][1] * v.y + r.m[2][1] * v.z,
          r.m[0][2] * v.x + r.m[1][2] * v.y + r.m[2][2] * v.z};
}

}  // namespace aloft
