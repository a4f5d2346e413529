#include "diagnose/2_model/canonical_rotation.hpp"

#include <cmath>

#include "aloft/dynamics/rotation.hpp"

namespace aloft::host::diagnose {

Eigen::Quaterniond canonical_rotation(const Eigen::Quaterniond& r, const NominalInertia& nominal,
                                      bool right) {
  using Vec3 = Eigen::Vector3d;
  const Vec3 m = nominal.principal_moments;
  const Eigen::Matrix3d axes = nominal.principal_axes.toRotationMatrix();
  const double tol = 1e-3 * m.sum();
  auto compose = [&](const Eigen::Quaterniond& s) {
    return right ? Eigen::Quaterniond(r * s) : Eigen::Quaterniond(s * r);
  };
  auto smaller = [](const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
    return std::abs(a.w()) > std::abs(b.w());
  };
  if (m(2) - m(0) < tol) return Eigen::Quaterniond::Identity();  // a sphere: any turn is none
  int symmetric_axis = -1;
  if (m(1) - m(0) < tol) symmetric_axis = 2;
  if (m(2) - m(1) < tol) symmetric_axis = 0;
  Eigen::Quaterniond best = r;
  if (symmetric_axis >= 0) {
    // Turns about the symmetry axis a: |w| of r*q(phi) or q(phi)*r is largest at
    // phi = -2 atan2(v.a, w) (v, w of r); a half turn about a perpendicular axis too.
    const Vec3 a = axes.col(symmetric_axis);
    for (const Vec3& flip_axis : {Vec3::Zero().eval(), axes.col((symmetric_axis + 1) % 3).eval()}) {
      const Eigen::Quaterniond flip =
          flip_axis.isZero() ? Eigen::Quaterniond::Identity()
                             : Eigen::Quaterniond(0.0, flip_axis.x(), flip_axis.y(), flip_axis.z());
      const Eigen::Quaterniond base = compose(flip);
      const double phi = -2.0 * std::atan2(base.vec().dot(a), base.w());
      const Eigen::Quaterniond turn(Eigen::AngleAxisd(phi, a));
      const Eigen::Quaterniond candidate =
          right ? Eigen::Quaterniond(base * turn) : Eigen::Quaterniond(turn * base);
      if (smaller(candidate, best)) best = candidate;
    }
  } else {
    for (int i = 0; i < 3; ++i) {
      const Vec3 p = axes.col(i);
      const Eigen::Quaterniond candidate = compose(Eigen::Quaterniond(0.0, p.x(), p.y(), p.z()));
      if (smaller(candidate, best)) best = candidate;
    }
  }
  return best.w() < 0 ? Eigen::Quaterniond(-best.w(), -best.x(), -best.y(), -best.z()) : best;
}

void describe_rotation(EffectParameters& p, const Eigen::VectorXd& theta, const NominalInertia& nominal,
                       bool right) {
  constexpr double kDeg = 180.0 / 3.14159265358979323846;
  p.rotation = canonical_rotation(quat_exp<double>(theta.head<3>()), nominal, right);
  p.angle_deg = angle_between<double>(Eigen::Quaterniond::Identity(), p.rotation) * kDeg;
}

}  // namespace aloft::host::diagnose
