#include "common/tensor_estimate_json.hpp"

#include "common/shortest_decimal.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace aloft::host {
namespace {

using nlohmann::json;

constexpr double kRadToDeg = 57.29577951308232;

json interval(double value, double half_width) {
  return json::array({value - half_width, value + half_width});
}

}  // namespace

json tensor_estimate_json(const TensorEstimate<float>& e) {
  json j;
  j["determined"] = e.determined;
  if (!e.determined) {
    for (const char* key : {"principal_ratios", "principal_ratios_95", "axes", "axes_95_deg",
                            "principal_kg_m2", "principal_kg_m2_95"})
      j[key] = nullptr;
    j["note"] = describe(e.note);
    return j;
  }
  const double r[2] = {double(e.ratio(0)), double(e.ratio(1))};
  j["principal_ratios"] = {shortest_decimal(e.ratio(0)), shortest_decimal(e.ratio(1))};
  j["principal_ratios_95"] = {interval(r[0], e.ratios_95[0]), interval(r[1], e.ratios_95[1])};
  j["axes"] = {shortest_decimal(e.axes.w()), shortest_decimal(e.axes.x()), shortest_decimal(e.axes.y()),
               shortest_decimal(e.axes.z())};
  j["axes_95_deg"] = {e.axes_95_rad(0) * kRadToDeg, e.axes_95_rad(1) * kRadToDeg,
                      e.axes_95_rad(2) * kRadToDeg};
  if (e.absolute) {
    j["principal_kg_m2"] = {shortest_decimal(e.principal(0)), shortest_decimal(e.principal(1)),
                            shortest_decimal(e.principal(2))};
    j["principal_kg_m2_95"] = {interval(e.principal(0), e.principal_95(0)),
                               interval(e.principal(1), e.principal_95(1)),
                               interval(e.principal(2), e.principal_95(2))};
  } else {
    j["principal_kg_m2"] = nullptr;
    j["principal_kg_m2_95"] = nullptr;
    j["note"] = "ratios and axes only: absolute moments need a rotor whose speed is logged";
  }
  return j;
}

TensorEstimate<float> tensor_estimate_of(const FlightRecordTensor& t) {
  TensorEstimate<float> e;
  e.determined = t.determined;
  e.absolute = t.absolute;
  e.note = static_cast<TensorEstimateNote>(t.note);
  const float xyz2 =
      t.axes_xyz[0] * t.axes_xyz[0] + t.axes_xyz[1] * t.axes_xyz[1] + t.axes_xyz[2] * t.axes_xyz[2];
  e.axes = Quat<float>(std::sqrt(std::fmax(0.0f, 1.0f - xyz2)), t.axes_xyz[0], t.axes_xyz[1], t.axes_xyz[2]);
  for (int i = 0; i < 3; ++i) {
    e.principal(i) = t.principal[i];
    e.principal_95(i) = t.principal_95[i];
    e.axes_95_rad(i) = t.axes_95_rad[i];
  }
  e.ratios_95[0] = t.ratios_95[0];
  e.ratios_95[1] = t.ratios_95[1];
  return e;
}

std::string tensor_estimate_text(const TensorEstimate<float>& e) {
  char line[400];
  if (!e.determined) {
    std::snprintf(line, sizeof line, "not determined: %s", describe(e.note));
    return line;
  }
  int n = std::snprintf(
      line, sizeof line, "I1/I3 %.4f ± %.4f, I2/I3 %.4f ± %.4f; axes held within %.2f %.2f %.2f deg",
      double(e.ratio(0)), double(e.ratios_95[0]), double(e.ratio(1)), double(e.ratios_95[1]),
      e.axes_95_rad(0) * kRadToDeg, e.axes_95_rad(1) * kRadToDeg, e.axes_95_rad(2) * kRadToDeg);
  if (e.absolute && n > 0 && n < static_cast<int>(sizeof line))
    std::snprintf(line + n, sizeof line - static_cast<std::size_t>(n),
                  "; moments %.4g ± %.2g, %.4g ± %.2g, %.4g ± %.2g kg·m²", double(e.principal(0)),
                  double(e.principal_95(0)), double(e.principal(1)), double(e.principal_95(1)),
                  double(e.principal(2)), double(e.principal_95(2)));
  return line;
}

}  // namespace aloft::host
