// What the firmwares' build-time generators (make_replay_source.cpp, make_fifo_throw.cpp
// and bake_flight_inertia.cpp, all here) write: of a body file's replay settings, C++
// definitions of PREFIX_inertia_kg_m2, PREFIX_sensor_to_body_wxyz,
// PREFIX_imu_position_known and PREFIX_imu_position_m; of an inertia tensor, its parts as
// make_from_tensor derived them (aloft::InertiaTensorParts). Floats are written with 9
// significant digits, which read back as the same float.
#pragma once

#include <cstdio>
#include <string>

#include "replay/replay_run.hpp"

namespace aloft_host_tools {

inline std::string float_literal(float v) {
  char text[40];
  std::snprintf(text, sizeof(text), "%.9g", static_cast<double>(v));
  std::string s = text;
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s + "f";
}

// `const aloft::InertiaTensorParts<float> NAME = {...};`
inline void write_inertia_parts_source(std::FILE* out, const aloft::InertiaTensor<float>& inertia,
                                       const char* name) {
  const aloft::InertiaTensorParts<float> p = inertia.parts();
  const auto list = [out](const float* v, int n) {
    std::fprintf(out, "{");
    for (int i = 0; i < n; ++i) std::fprintf(out, "%s%s", i > 0 ? ", " : "", float_literal(v[i]).c_str());
    std::fprintf(out, "}");
  };
  std::fprintf(out, "const aloft::InertiaTensorParts<float> %s = {\n    ", name);
  list(p.tensor, 9);
  std::fprintf(out, ",\n    ");
  list(p.inverse, 9);
  std::fprintf(out, ",\n    ");
  list(p.principal_moments, 3);
  std::fprintf(out, ",\n    ");
  list(p.principal_axes_wxyz, 4);
  std::fprintf(out, "};\n");
}

inline void write_settings_source(std::FILE* out, const aloft::host::ReplaySettings& settings,
                                  const char* prefix) {
  std::fprintf(out, "const float %s_inertia_kg_m2[3][3] = {\n", prefix);
  for (int r = 0; r < 3; ++r) {
    std::fprintf(out, "    {%s, %s, %s},\n", float_literal(settings.tensor_kg_m2(r, 0)).c_str(),
                 float_literal(settings.tensor_kg_m2(r, 1)).c_str(),
                 float_literal(settings.tensor_kg_m2(r, 2)).c_str());
  }
  const aloft::Quat<float>& q = settings.sensor_to_body;
  std::fprintf(out, "};\nconst float %s_sensor_to_body_wxyz[4] = {%s, %s, %s, %s};\n", prefix,
               float_literal(q.w()).c_str(), float_literal(q.x()).c_str(), float_literal(q.y()).c_str(),
               float_literal(q.z()).c_str());
  const aloft::Vec3<float> r = settings.imu_position_m.value_or(aloft::Vec3<float>::Zero());
  std::fprintf(out, "const bool %s_imu_position_known = %s;\n", prefix,
               settings.imu_position_m ? "true" : "false");
  std::fprintf(out, "const float %s_imu_position_m[3] = {%s, %s, %s};\n", prefix,
               float_literal(r.x()).c_str(), float_literal(r.y()).c_str(), float_literal(r.z()).c_str());
}

}  // namespace aloft_host_tools
