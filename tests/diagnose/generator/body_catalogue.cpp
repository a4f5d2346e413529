#include "body_catalogue.hpp"

#include <Eigen/Geometry>
#include <stdexcept>

namespace aloft::generator {
namespace {

Eigen::Matrix3d solid_box(double mass, double x, double y, double z) {
  const double k = mass / 12.0;
  return Eigen::Vector3d(k * (y * y + z * z), k * (x * x + z * z), k * (x * x + y * y)).asDiagonal();
}

Eigen::Matrix3d solid_cylinder_z(double mass, double radius, double height) {
  const double transverse = mass * (3.0 * radius * radius + height * height) / 12.0;
  const double axial = mass * radius * radius / 2.0;
  return Eigen::Vector3d(transverse, transverse, axial).asDiagonal();
}

}  // namespace

const std::vector<std::string>& body_names() {
  static const std::vector<std::string> names = {"cylinder", "disc", "box", "tilted_box", "racquet"};
  return names;
}

BodyModel body_model(const std::string& name) {
  BodyModel b;
  b.name = name;
  if (name == "cylinder") {
    // The seed paper's steel cylinder (STUDY.md): 10.010 kg, 97.0 mm high, 129.8 mm
    // across; GF moments 183.8, 183.8, 210.8 kg·cm², near-symmetric about z.
    b.mass_kg = 10.010;
    b.inertia_kg_m2 = solid_cylinder_z(b.mass_kg, 0.0649, 0.097);
    b.marker_semi_axes_m = Eigen::Vector3d(0.0649, 0.0649, 0.0485);
    b.imu_offset_m = Eigen::Vector3d(0.03, 0.0, 0.0485);
  } else if (name == "disc") {
    // A flying-disc-like flat cylinder: axial moment twice the transverse one.
    b.mass_kg = 0.6;
    b.inertia_kg_m2 = solid_cylinder_z(b.mass_kg, 0.12, 0.02);
    b.marker_semi_axes_m = Eigen::Vector3d(0.12, 0.12, 0.01);
    b.imu_offset_m = Eigen::Vector3d(0.0, 0.05, 0.01);
  } else if (name == "box") {
    // A shoebox-sized block: three well separated moments.
    b.mass_kg = 0.9;
    b.inertia_kg_m2 = solid_box(b.mass_kg, 0.07, 0.14, 0.22);
    b.marker_semi_axes_m = Eigen::Vector3d(0.035, 0.07, 0.11);
    b.imu_offset_m = Eigen::Vector3d(0.035, 0.02, -0.03);
  } else if (name == "tilted_box") {
    // A block whose principal axes are not the body axes (a body frame fixed to some
    // other feature of the object): the tensor has off-diagonal entries.
    b.mass_kg = 1.5;
    const Eigen::Matrix3d r =
        Eigen::AngleAxisd(0.45, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
    b.inertia_kg_m2 = r * solid_box(b.mass_kg, 0.06, 0.11, 0.17) * r.transpose();
    b.marker_semi_axes_m = Eigen::Vector3d(0.07, 0.08, 0.09);
    b.imu_offset_m = Eigen::Vector3d(0.0, -0.03, 0.02);
  } else if (name == "racquet") {
    // A tennis-racquet-like flat body, handle along y, face in the x-y plane: small
    // moment about the handle, I_z just below I_x + I_y (nearly a plane lamina), so
    // spin near the intermediate axis x flips (the tennis racket theorem).
    b.mass_kg = 0.32;
    b.inertia_kg_m2 = Eigen::Vector3d(0.0142, 0.00155, 0.0155).asDiagonal();
    b.marker_semi_axes_m = Eigen::Vector3d(0.13, 0.33, 0.02);
    b.imu_offset_m = Eigen::Vector3d(0.0, -0.2, 0.0);
  } else {
    throw std::invalid_argument("unknown body '" + name + "'");
  }
  return b;
}

int symmetry_axis_index(const Eigen::Vector3d& m, double relative) {
  const bool low_pair = (m(1) - m(0)) <= relative * m(1);
  const bool high_pair = (m(2) - m(1)) <= relative * m(2);
  if (low_pair && !high_pair) return 2;
  if (high_pair && !low_pair) return 0;
  return -1;  // all distinct, or all three equal (a sphere: no preferred axis at all)
}

}  // namespace aloft::generator
