// Eigen values as the report's JSON writes them: vectors as [x, y, z], matrices as rows,
// quaternions as [w, x, y, z] (SPEC §4).
#pragma once

#include <nlohmann/json.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace aloft::host::diagnose {

inline nlohmann::json json_vec(const Eigen::Vector3d& v) { return nlohmann::json::array({v(0), v(1), v(2)}); }

inline nlohmann::json json_matrix(const Eigen::Matrix3d& m) {
  return nlohmann::json::array(
      {json_vec(m.row(0).transpose()), json_vec(m.row(1).transpose()), json_vec(m.row(2).transpose())});
}

inline nlohmann::json json_quat(const Eigen::Quaterniond& q) {
  return nlohmann::json::array({q.w(), q.x(), q.y(), q.z()});
}

}  // namespace aloft::host::diagnose
