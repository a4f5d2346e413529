// Host side of the example: reads the flight the firmware carries, from the files of
// SPEC §2 (body, "inertia": {"tensor": ...} form) and §3 (IMU log, plain t,gx,gy,gz
// layout). Errors are std::runtime_error with one line naming the file, the line where
// possible, and the problem.
#pragma once

#include <Eigen/Core>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace aloft_example {

struct HostGyroSample {
  double t_s;
  Eigen::Vector3d omega_rad_s;
};

inline Eigen::Matrix3d read_inertia_tensor(const std::string& body_path) {
  std::ifstream in(body_path);
  if (!in) throw std::runtime_error(body_path + ": cannot open");
  nlohmann::json body;
  try {
    in >> body;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(body_path + ": not JSON: " + e.what());
  }
  const nlohmann::json* tensor = nullptr;
  if (body.is_object() && body.contains("inertia") && body["inertia"].is_object() &&
      body["inertia"].contains("tensor")) {
    tensor = &body["inertia"]["tensor"];
  }
  if (tensor == nullptr || !tensor->is_array() || tensor->size() != 3) {
    throw std::runtime_error(body_path + ": needs inertia.tensor, a 3x3 array (kg m^2)");
  }
  Eigen::Matrix3d result;
  for (int r = 0; r < 3; ++r) {
    const auto& row = (*tensor)[static_cast<std::size_t>(r)];
    if (!row.is_array() || row.size() != 3) {
      throw std::runtime_error(body_path + ": inertia.tensor row " + std::to_string(r + 1) +
                               " is not 3 numbers");
    }
    for (int c = 0; c < 3; ++c) result(r, c) = row[static_cast<std::size_t>(c)].get<double>();
  }
  return result;
}

inline std::vector<HostGyroSample> read_gyro_log(const std::string& imu_path) {
  std::ifstream in(imu_path);
  if (!in) throw std::runtime_error(imu_path + ": cannot open");
  std::string line;
  std::getline(in, line);
  if (line.rfind("t,gx,gy,gz", 0) != 0) {
    throw std::runtime_error(imu_path + ":1: expected the header t,gx,gy,gz");
  }
  std::vector<HostGyroSample> samples;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    std::istringstream fields(line);
    double v[4];
    char comma = ',';
    fields >> v[0];
    for (int i = 1; i < 4 && fields; ++i) fields >> comma >> v[i];
    if (!fields || comma != ',') {
      throw std::runtime_error(imu_path + ":" + std::to_string(number) +
                               ": expected four numbers t,gx,gy,gz");
    }
    if (!samples.empty() && !(v[0] > samples.back().t_s)) {
      throw std::runtime_error(imu_path + ":" + std::to_string(number) + ": time does not increase");
    }
    samples.push_back({v[0], Eigen::Vector3d(v[1], v[2], v[3])});
  }
  if (samples.size() < 2) throw std::runtime_error(imu_path + ": fewer than two samples");
  return samples;
}

}  // namespace aloft_example
