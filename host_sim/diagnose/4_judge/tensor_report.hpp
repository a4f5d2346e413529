// The tensor report (SPEC §4 `tensor`): how well the data pin down the nominal tensor.
// Principal-moment ratios I2/I1 and I3/I1 in the body file's axis order, their 95 %
// intervals, the angle within which the principal axes are held, and whether the nominal
// ratios lie inside the intervals.
// How they are made: tensor_intervals.hpp.
#pragma once

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

#include "diagnose/2_model/nominal_inertia.hpp"

namespace aloft::host::diagnose {

struct TensorReport {
  Eigen::Vector2d ratio_best = Eigen::Vector2d::Ones();  // I2/I1, I3/I1 (body file order)
  Eigen::Vector2d ratio_low = Eigen::Vector2d::Ones(), ratio_high = Eigen::Vector2d::Ones();
  Eigen::Vector2d ratio_nominal = Eigen::Vector2d::Ones();
  Eigen::Vector3i axis_order = Eigen::Vector3i(0, 1, 2);  // body axis b holds principal axis_order(b)
  double axes_95_deg = 0.0;
  bool axes_known = false;  // false: no axes fit to judge them by
  bool consistent_with_nominal = true;
  // Near-symmetric bodies: pairs of body axes (a < b) whose principal moments the data
  // cannot tell apart (the 95 % interval of their ratio holds 1). Within such a plane the
  // principal axes are not fixed, so no axes angle is given (axes_known false); the
  // moments (kg·m², body axis order, from the moments fit) name what the data do hold.
  std::vector<std::array<int, 2>> unresolved_planes;
  Eigen::Vector3d moments_kg_m2 = Eigen::Vector3d::Zero();
  int flights = 1;
  std::string method;
};

// The nominal principal axis (index into the ascending moments) nearest each body axis.
Eigen::Vector3i principal_axis_order(const NominalInertia& nominal);

// ", Ix and Iy cannot be told apart (...): the axes in the x-y plane are not fixed" for
// one unresolved plane, "no principal axis is fixed" for more; empty when none.
std::string unresolved_planes_text(const TensorReport& report);

// "the 6 flights hold I2/I1 to 0.27 ± 0.01 ...": the line the summary leads with.
std::string tensor_summary(const TensorReport& report);

}  // namespace aloft::host::diagnose
