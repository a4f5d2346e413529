#include "diagnose/4_judge/tensor_report.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace aloft::host::diagnose {

Eigen::Vector3i principal_axis_order(const NominalInertia& nominal) {
  const Eigen::Matrix3d axes = nominal.principal_axes.toRotationMatrix();
  Eigen::Vector3i best(0, 1, 2);
  double best_score = -1.0;
  std::array<int, 3> perm = {0, 1, 2};
  do {
    const double score = std::abs(axes(0, perm[0])) + std::abs(axes(1, perm[1])) + std::abs(axes(2, perm[2]));
    if (score > best_score) {
      best_score = score;
      best = Eigen::Vector3i(perm[0], perm[1], perm[2]);
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  return best;
}

std::string unresolved_planes_text(const TensorReport& r) {
  static const char* axis = "xyz";
  char text[200];
  const auto& planes = r.unresolved_planes;
  if (planes.empty()) return "";
  if (planes.size() == 1) {
    const int a = planes[0][0], b = planes[0][1];
    std::snprintf(
        text, sizeof text,
        ", I%c and I%c cannot be told apart (%.4g and %.4g kg m^2): the axes in the %c-%c plane are "
        "not fixed",
        axis[a], axis[b], r.moments_kg_m2(a), r.moments_kg_m2(b), axis[a], axis[b]);
  } else {
    std::snprintf(
        text, sizeof text,
        ", no two moments can be told apart (Ix %.4g, Iy %.4g, Iz %.4g kg m^2): no principal axis is "
        "fixed",
        r.moments_kg_m2(0), r.moments_kg_m2(1), r.moments_kg_m2(2));
  }
  return text;
}

std::string tensor_summary(const TensorReport& r) {
  static const char* axis = "xyz";
  char text[512];
  const auto half = [&](int i) { return 0.5 * (r.ratio_high(i) - r.ratio_low(i)); };
  std::snprintf(text, sizeof text,
                "tensor: %s %d flight%s hold%s I%c/I%c to %.4g +- %.2g and I%c/I%c to %.4g +- %.2g (95 %%)",
                r.flights == 1 ? "this" : "the", r.flights, r.flights == 1 ? "" : "s",
                r.flights == 1 ? "s" : "", axis[1], axis[0], r.ratio_best(0), half(0), axis[2], axis[0],
                r.ratio_best(1), half(1));
  std::string out = text;
  if (r.axes_known) {
    std::snprintf(text, sizeof text, ", principal axes within %.2g deg", r.axes_95_deg);
    out += text;
  }
  out += unresolved_planes_text(r);
  std::string outside;
  for (int i = 0; i < 2; ++i) {
    if (r.ratio_nominal(i) >= r.ratio_low(i) && r.ratio_nominal(i) <= r.ratio_high(i)) continue;
    std::snprintf(text, sizeof text, "%sthe nominal I%c/I%c %.3g lies outside", outside.empty() ? "" : ", ",
                  axis[i + 1], axis[0], r.ratio_nominal(i));
    outside += text;
  }
  std::snprintf(text, sizeof text, ": %s\n",
                outside.empty() ? "the nominal ratios lie inside (the tensor holds)" : outside.c_str());
  out += text;
  return out;
}

}  // namespace aloft::host::diagnose
