// The tensor a flight itself shows, estimated as it flies (the streaming estimator is
// being written; this file holds what it reports, which FlightResult carries).
#pragma once

#include <cstdint>

#include "aloft/dynamics/rotation.hpp"

namespace aloft {

// Why an estimate is not determined (TensorEstimate::note).
enum class TensorEstimateNote : std::uint8_t {
  determined = 0,      // the flight fixes the ratios and the axes
  too_short,           // too few pieces of flight
  too_little_turning,  // the body hardly turned (a drop)
  one_axis_spin,       // a spin about one principal axis: the other two moments are not seen
};

template <typename Scalar>
struct TensorEstimate {
  bool determined = false;
  bool absolute = false;  // principal is in kg·m²: a rotor's known momentum gave the scale
  TensorEstimateNote note = TensorEstimateNote::too_short;
  // Principal moments, ascending: kg·m² when absolute, else scaled so that the largest is 1
  // (principal(0), principal(1) are then the ratios I1/I3, I2/I3).
  Vec3<Scalar> principal = Vec3<Scalar>::Zero();
  Vec3<Scalar> principal_95 = Vec3<Scalar>::Zero();  // 95 % half-widths, when absolute
  Scalar ratios_95[2] = {Scalar(0), Scalar(0)};      // 95 % half-widths of I1/I3, I2/I3
  Quat<Scalar> axes = Quat<Scalar>::Identity();      // principal frame into body axes
  Vec3<Scalar> axes_95_rad = Vec3<Scalar>::Zero();   // each principal axis held within (95 %)

  Scalar ratio(int i) const { return principal(i) / principal(2); }
};

}  // namespace aloft
