// The bodies the flight generator throws. Each is a plausible thrown object with its
// true inertia tensor about the centre of mass in body axes (kg·m²), and the size of
// the surface that markers are stuck on. Chosen to span the cases a diagnosis meets:
// near-symmetric (the seed paper's cylinder, a disc), clearly asymmetric (box),
// principal axes off the body axes (tilted_box, a full tensor), and flat with an
// unstable intermediate axis (racquet, I3 ≈ I1 + I2).
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace aloft::generator {

struct BodyModel {
  std::string name;
  double mass_kg = 0.0;
  Eigen::Matrix3d inertia_kg_m2 = Eigen::Matrix3d::Identity();
  // Markers are placed on the ellipsoid with these semi-axes (body axes, metres).
  Eigen::Vector3d marker_semi_axes_m = Eigen::Vector3d::Constant(0.05);
  // Where the IMU sits, from the centre of mass (body axes): the accelerometer sees the
  // centripetal and tangential acceleration of this point.
  Eigen::Vector3d imu_offset_m = Eigen::Vector3d::Zero();
};

// Names accepted by body_model(), in a fixed order.
const std::vector<std::string>& body_names();

// Throws std::invalid_argument for an unknown name.
BodyModel body_model(const std::string& name);

// Index of the principal moment that is not paired with another within `relative`
// (0, 1, 2 in ascending order of moments), or -1 when all three are distinct.
// A body of revolution moves the same whatever rotation about its symmetry axis is
// applied to its tensor or its sensor, so such rotations are unobservable and the
// generator avoids them.
int symmetry_axis_index(const Eigen::Vector3d& ascending_moments, double relative = 0.02);

}  // namespace aloft::generator
