#include "common/inertia_scale_check.hpp"

#include <cmath>
#include <cstdio>

namespace aloft::host {
namespace {

struct MomentUnit {
  const char* name;
  double kg_m2;  // one of it in kg·m²
};

// Units moments are often written in; the likely one brings k nearest the body's size.
constexpr MomentUnit kMomentUnits[] = {
    {"g·cm²", 1e-7}, {"g·mm²", 1e-9}, {"kg·cm²", 1e-4}, {"kg·mm²", 1e-6}, {"g·m²", 1e-3}};

double farthest_marker_m(const Body& body) {
  double r = 0.0;
  for (const auto& marker : body.markers_m) r = std::max(r, marker.second.norm());
  return r;
}

}  // namespace

std::optional<std::string> inertia_scale_problem(const Body& body) {
  if (!(body.mass_kg > 0.0)) return std::nullopt;
  const double largest = body.inertia.principal_moments().maxCoeff();
  const double k = std::sqrt(largest / body.mass_kg);
  const double extent = farthest_marker_m(body);
  const double bound = extent > 0.0 ? 2.0 * extent : kLargestRadiusOfGyration_m;
  if (k <= bound) return std::nullopt;
  // The unit that brings k nearest a likely k: half the markers' extent, or without
  // markers that of a hand-sized body, 5 cm.
  const double typical = extent > 0.0 ? 0.5 * extent : 0.05;
  const auto miss = [&](const MomentUnit& u) { return std::abs(std::log(k * std::sqrt(u.kg_m2) / typical)); };
  const MomentUnit* likely = &kMomentUnits[0];
  for (const MomentUnit& u : kMomentUnits) {
    if (miss(u) < miss(*likely)) likely = &u;
  }
  char where[96];
  if (extent > 0.0) {
    std::snprintf(where, sizeof where, "its farthest marker lies %.3g m from the centre of mass", extent);
  } else {
    std::snprintf(where, sizeof where, "no body one throws has over %.0f m", kLargestRadiusOfGyration_m);
  }
  char head[240];
  std::snprintf(head, sizeof head,
                "the largest principal moment, %.4g kg·m², on a %.4g kg body means a radius of gyration of "
                "%.3g m, where %s",
                largest, body.mass_kg, k, where);
  char guess[120] = ": check the moments' unit (kg·m²), the mass and the markers";
  if (miss(*likely) < std::log(4.0)) {
    std::snprintf(guess, sizeof guess, ": are the moments in %s (%.4g kg·m²)?", likely->name,
                  largest * likely->kg_m2);
  }
  const std::string message =
      std::string(head) + guess +
      " Ratios, and so the verdict, are the same; reported moments are in the file's unit";
  return message;
}

}  // namespace aloft::host
