// The inertia tensor of a rigid body about its centre of mass, in body axes (kg·m²).
// Off-diagonal entries are the matrix entries (Ixy = -∫xy dm), as in SPEC §2.
//
// An InertiaTensor is only ever built through the make_* functions, which validate
// (symmetric, positive definite, triangle inequality of the principal moments) and
// precompute the inverse and the principal decomposition the integrators need.
#pragma once

#include "aloft/cold_path.hpp"
#include "aloft/dynamics/rotation.hpp"
#include "aloft/status.hpp"
#include "aloft/dynamics/symmetric_eigen.hpp"

namespace aloft {

// What make_from_tensor derives from a tensor, as plain numbers a build step can bake into
// a firmware image (port/host_tools/bake_flight_inertia.cpp), so that the image carries
// neither the eigen decomposition nor the tensor's checks, which run once.
template <typename Scalar>
struct InertiaTensorParts {
  Scalar tensor[9];               // column-major
  Scalar inverse[9];              // column-major
  Scalar principal_moments[3];    // ascending
  Scalar principal_axes_wxyz[4];  // unit quaternion, principal axes into body axes
};

template <typename Scalar>
class InertiaTensor {
 public:
  // Default: the unit sphere-like tensor (identity), valid but only a placeholder.
  InertiaTensor() = default;

  const Mat3<Scalar>& tensor() const { return tensor_; }
  const Mat3<Scalar>& inverse() const { return inverse_; }
  // Principal moments, ascending.
  const Vec3<Scalar>& principal_moments() const { return principal_moments_; }
  // Maps principal axes into body axes: column i of R(principal_axes()) is principal
  // axis i in body coordinates. Right-handed.
  const Quat<Scalar>& principal_axes() const { return principal_axes_; }

  // Relative tolerance of the validity checks: rounding of a tensor given in text.
  static constexpr Scalar relative_tolerance() { return Scalar(1e-5); }

  // From a full symmetric tensor in body axes. `triangle_slack` (relative to the sum of
  // the moments) is how far a principal moment may exceed the sum of the other two: by
  // default rounding only; a host reading *measured* moments of a flat body may allow
  // their uncertainty (see host_sim/common/body_file.cpp).
  ALOFT_COLD static Status make_from_tensor(const Mat3<Scalar>& tensor, InertiaTensor& out,
                                            Scalar triangle_slack = relative_tolerance()) {
    for (int i = 0; i < 9; ++i) {
      if (!std::isfinite(tensor.data()[i])) return Status::non_finite_input;
    }
    const Scalar scale = tensor.cwiseAbs().maxCoeff();
    if (!(scale > Scalar(0))) return Status::tensor_not_positive_definite;
    if ((tensor - tensor.transpose()).cwiseAbs().maxCoeff() > relative_tolerance() * scale) {
      return Status::tensor_not_symmetric;
    }
    const Mat3<Scalar> symmetric = Scalar(0.5) * (tensor + tensor.transpose());
    Vec3<Scalar> moments;
    Mat3<Scalar> axes;
    symmetric_eigen_decomposition(symmetric, moments, axes);  // ascending, right-handed
    if (!(moments(0) > relative_tolerance() * scale)) return Status::tensor_not_positive_definite;
    const Status triangle = check_triangle(moments, triangle_slack);
    if (triangle != Status::ok) return triangle;
    out.tensor_ = symmetric;
    out.inverse_ = symmetric.inverse();
    out.principal_moments_ = moments;
    out.principal_axes_ = Quat<Scalar>(axes).normalized();
    return Status::ok;
  }

  // The parts of a tensor that make_from_tensor accepted, as it derived them.
  InertiaTensorParts<Scalar> parts() const {
    InertiaTensorParts<Scalar> p;
    for (int i = 0; i < 9; ++i) {
      p.tensor[i] = tensor_.data()[i];
      p.inverse[i] = inverse_.data()[i];
    }
    for (int i = 0; i < 3; ++i) p.principal_moments[i] = principal_moments_(i);
    const Scalar q[4] = {principal_axes_.w(), principal_axes_.x(), principal_axes_.y(), principal_axes_.z()};
    for (int i = 0; i < 4; ++i) p.principal_axes_wxyz[i] = q[i];
    return p;
  }

  // The same tensor again from its parts, not checked again: only from parts() of a tensor
  // that make_from_tensor accepted (a firmware's build step does that on the build machine
  // and stops the build when the tensor is rejected).
  static InertiaTensor from_accepted_parts(const InertiaTensorParts<Scalar>& p) {
    InertiaTensor out;
    out.tensor_ = Eigen::Map<const Mat3<Scalar>>(p.tensor);
    out.inverse_ = Eigen::Map<const Mat3<Scalar>>(p.inverse);
    out.principal_moments_ = Eigen::Map<const Vec3<Scalar>>(p.principal_moments);
    const Scalar* q = p.principal_axes_wxyz;
    out.principal_axes_ = Quat<Scalar>(q[0], q[1], q[2], q[3]);
    return out;
  }

  // From principal moments (any order) and the rotation mapping the principal frame
  // into the body frame (identity: principal axes are body axes).
  static Status make_from_principal(const Vec3<Scalar>& moments, const Quat<Scalar>& axes, InertiaTensor& out,
                                    Scalar triangle_slack = relative_tolerance()) {
    if (!all_finite(moments) || !all_finite(axes)) return Status::non_finite_input;
    if (!is_unit(axes)) return Status::non_unit_quaternion;
    if (!(moments.minCoeff() > Scalar(0))) return Status::tensor_not_positive_definite;
    const Status triangle = check_triangle(moments, triangle_slack);
    if (triangle != Status::ok) return triangle;
    const Mat3<Scalar> r = axes.normalized().toRotationMatrix();
    const Mat3<Scalar> tensor = r * moments.asDiagonal() * r.transpose();
    // Keep the given moments and axes exactly rather than re-deriving them.
    out.tensor_ = Scalar(0.5) * (tensor + tensor.transpose());
    out.inverse_ = r * moments.cwiseInverse().asDiagonal() * r.transpose();
    sort_principal(moments, r, out);
    return Status::ok;
  }

  // Solid homogeneous cylinder, axis along body z.
  static Status make_cylinder(Scalar mass, Scalar radius, Scalar height, InertiaTensor& out) {
    if (!positive(mass) || !positive(radius) || !positive(height)) return Status::invalid_dimension;
    const Scalar r2 = radius * radius;
    const Scalar transverse = mass * (Scalar(3) * r2 + height * height) / Scalar(12);
    const Scalar axial = mass * r2 / Scalar(2);
    return make_from_principal(Vec3<Scalar>(transverse, transverse, axial), Quat<Scalar>::Identity(), out);
  }

  // Solid homogeneous box with edge lengths x, y, z along the body axes.
  static Status make_box(Scalar mass, Scalar x, Scalar y, Scalar z, InertiaTensor& out) {
    if (!positive(mass) || !positive(x) || !positive(y) || !positive(z)) {
      return Status::invalid_dimension;
    }
    const Scalar k = mass / Scalar(12);
    return make_from_principal(Vec3<Scalar>(k * (y * y + z * z), k * (x * x + z * z), k * (x * x + y * y)),
                               Quat<Scalar>::Identity(), out);
  }

  // Solid homogeneous sphere.
  static Status make_sphere(Scalar mass, Scalar radius, InertiaTensor& out) {
    if (!positive(mass) || !positive(radius)) return Status::invalid_dimension;
    const Scalar i = Scalar(2) * mass * radius * radius / Scalar(5);
    return make_from_principal(Vec3<Scalar>(i, i, i), Quat<Scalar>::Identity(), out);
  }

  // Kinetic energy 1/2 w·Iw and angular momentum Iw (body axes) of body rate w.
  Scalar kinetic_energy(const Vec3<Scalar>& omega_body) const {
    return Scalar(0.5) * omega_body.dot(tensor_ * omega_body);
  }
  Vec3<Scalar> angular_momentum(const Vec3<Scalar>& omega_body) const { return tensor_ * omega_body; }

 private:
  static bool positive(Scalar v) { return std::isfinite(v) && v > Scalar(0); }

  // A physical body has every principal moment at most the sum of the other two
  // (equality: a flat plate), up to `relative_slack` of the sum of the moments.
  static Status check_triangle(const Vec3<Scalar>& m, Scalar relative_slack) {
    const Scalar slack = relative_slack * m.sum();
    if (m(0) > m(1) + m(2) + slack || m(1) > m(0) + m(2) + slack || m(2) > m(0) + m(1) + slack) {
      return Status::tensor_breaks_triangle_inequality;
    }
    return Status::ok;
  }

  // Stores moments ascending with their axes (columns of r), keeping the frame right-handed.
  static void sort_principal(const Vec3<Scalar>& moments, const Mat3<Scalar>& r, InertiaTensor& out) {
    int order[3] = {0, 1, 2};
    for (int i = 0; i < 3; ++i) {
      for (int j = i + 1; j < 3; ++j) {
        if (moments(order[j]) < moments(order[i])) {
          const int t = order[i];
          order[i] = order[j];
          order[j] = t;
        }
      }
    }
    Mat3<Scalar> axes;
    for (int i = 0; i < 3; ++i) {
      out.principal_moments_(i) = moments(order[i]);
      axes.col(i) = r.col(order[i]);
    }
    if (axes.determinant() < Scalar(0)) axes.col(2) = -axes.col(2);
    out.principal_axes_ = Quat<Scalar>(axes).normalized();
  }

  Mat3<Scalar> tensor_ = Mat3<Scalar>::Identity();
  Mat3<Scalar> inverse_ = Mat3<Scalar>::Identity();
  Vec3<Scalar> principal_moments_ = Vec3<Scalar>::Ones();
  Quat<Scalar> principal_axes_ = Quat<Scalar>::Identity();
};

}  // namespace aloft
