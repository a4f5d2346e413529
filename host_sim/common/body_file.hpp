// The body file of SPEC §2: name, mass, inertia (tensor | principal [+ axes] | shape),
// optional markers in body axes, optional IMU rotation (sensor -> body) and optional IMU
// position (the accelerometer's place in body axes from the centre of mass, metres) and
// optional rotor (a wheel, fan or motor inside the body whose speed is logged).
#pragma once

#include <map>
#include <optional>
#include <string>

#include "aloft/dynamics/inertia_tensor.hpp"

namespace aloft::host {

// Measured moments of a flat body (a racquet, a plate) often break the triangle
// inequality by a little, well inside their uncertainty; such a body is still worth
// simulating. Up to this share of the moments' sum a body file is accepted with a
// warning, and tensors drawn around it (the study's Monte Carlo) are held to the same.
constexpr double kMeasuredTriangleSlack = 0.05;

// SPEC §2 `rotor`: the rotor's moment about its spin axis and that axis in body axes
// (unit length). Its angular momentum relative to the body is inertia * speed * axis.
struct BodyRotor {
  double inertia_kg_m2 = 0.0;
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
};

struct Body {
  std::string name;
  double mass_kg = 0.0;
  InertiaTensor<double> inertia;
  std::map<std::string, Eigen::Vector3d> markers_m;  // body axes
  Eigen::Quaterniond imu_to_body = Eigen::Quaterniond::Identity();
  // `imu.position`; without it the onboard pipeline estimates the lever arm from the data.
  std::optional<Eigen::Vector3d> imu_position_m;
  // `rotor`; a body with one needs the rotor's speed in every recording (`rotor_rad_s`).
  std::optional<BodyRotor> rotor;
};

// Reads and validates a body file; throws aloft::host::Error with one line naming the
// file and the problem (missing key, wrong type, invalid tensor, ...).
Body read_body_file(const std::string& path);

// The same from JSON text already in memory; `source` names it in messages.
Body parse_body_json(const std::string& text, const std::string& source);

// The body named `source`: read from that file, or, where `json_text` is not empty, from
// that text (a body handed over in memory, as the Python module's dict bodies are).
Body read_body(const std::string& source, const std::string& json_text);

}  // namespace aloft::host
