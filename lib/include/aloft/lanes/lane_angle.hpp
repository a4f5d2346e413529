// The angle atan2(y, x) for y >= 0 (so in [0, pi]), written for lane types
// (aloft/lanes/lanes.hpp): the deviation angle of every simulation, in SIMD lanes on the host
// and without the C library's software atan2f on a Cortex-M4F, whose FPU has no
// transcendental instructions.
//
// Method: fold (y, |x|) into the first octant (t = min/max in [0, 1]); past tan(pi/8)
// use atan(t) = pi/4 + atan((t - 1)/(t + 1)), so the polynomial argument u stays within
// |u| <= tan(pi/8) = 0.414; unfold with pi/2 - a and pi - a. Only one division: u is a
// ratio of min/max or of their difference and sum, chosen before dividing.
// Polynomials: double, fdlibm's s_atan.c (11 terms, minimax for |u| <= 7/16, error
// below 1 ulp); float, Cephes' atanf (4 terms, relative error about 1e-7 on the same
// interval). tests/core/test_lane_angle.cpp bounds the error against std::atan2.
#pragma once

#include <cmath>

#include "aloft/lanes/lanes.hpp"

namespace aloft {
namespace detail {

// atan(u) for |u| <= 7/16 (u odd: u - u z P(z), z = u^2).
template <typename T>
inline T atan_reduced(const T& u, double /*precision tag*/) {
  const T z = u * u;
  const T w = z * z;
  // Even and odd halves of the series, evaluated apart to halve the dependency chain.
  const T s1 =
      z * (T(3.33333333333329318027e-01) +
           w * (T(1.42857142725034663711e-01) +
                w * (T(9.09088713343650656196e-02) +
                     w * (T(6.66107313738753120669e-02) +
                          w * (T(4.97687799461593236017e-02) + w * T(1.62858201153657823623e-02))))));
  const T s2 = w * (T(-1.99999999998764832476e-01) +
                    w * (T(-1.11111104054623557880e-01) +
                         w * (T(-7.69187620504482999495e-02) +
                              w * (T(-5.83357013379057348645e-02) + w * T(-3.65315727442169155270e-02)))));
  return u - u * (s1 + s2);
}

template <typename T>
inline T atan_reduced(const T& u, float /*precision tag*/) {
  const T z = u * u;
  return ((((T(8.05374449538e-2f) * z - T(1.38776856032e-1f)) * z + T(1.99777106478e-1f)) * z -
           T(3.33329491539e-1f)) *
              z * u +
          u);
}

}  // namespace detail

// atan2(y, x) in [0, pi] for y >= 0, lane-wise (0 for y = x = 0).
template <typename T>
inline T nonnegative_atan2(const T& y, const T& x) {
  using Scalar = LaneScalar<T>;
  using std::abs;
  const T ax = abs(x);
  const auto steep = y > ax;  // past pi/4: pi/2 - atan(|x|/y)
  const T lo = select(steep, ax, y);
  const T hi = select(steep, y, ax);
  // tan(pi/8) = sqrt(2) - 1.
  const auto upper = lo > T(Scalar(0.41421356237309504880)) * hi;
  const T denominator = select(upper, lo + hi, hi);
  // (0, 0) gives 0, as std::atan2 does, rather than 0/0.
  const T u = select(upper, lo - hi, lo) / select(denominator > T(Scalar(0)), denominator, T(Scalar(1)));
  T a = detail::atan_reduced(u, Scalar(0));
  a = select(upper, a + T(Scalar(0.78539816339744830962)), a);
  a = select(steep, T(Scalar(1.57079632679489661923)) - a, a);
  return select(x < T(Scalar(0)), T(Scalar(3.14159265358979323846)) - a, a);
}

// The deviation angle atan2(|a x b|, a . b) of two vectors, lane-wise
// (aloft/dynamics/deviation.hpp has the Eigen form, which calls this).
template <typename T>
inline T lane_deviation_angle(const LaneVec3<T>& a, const LaneVec3<T>& b) {
  using std::sqrt;
  const T cx = a.y * b.z - a.z * b.y;
  const T cy = a.z * b.x - a.x * b.z;
  const T cz = a.x * b.y - a.y * b.x;
  return nonnegative_atan2(sqrt(cx * cx + cy * cy + cz * cz), a.x * b.x + a.y * b.y + a.z * b.z);
}

}  // namespace aloft
