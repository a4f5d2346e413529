// `inertia_moments`: the principal moments are wrong. theta = (u0, u1): moments
// n_i exp(u_i) (u2 = -u0-u1) along the nominal principal axes, rescaled to the nominal
// sum (gyro data and the torque-free equations cannot fix the scale).
#include <algorithm>
#include <cmath>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/2_model/printf_text.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

Vec3 moments_of(const NominalInertia& nominal, const Eigen::VectorXd& u01) {
  const Vec3 n = nominal.principal_moments;
  const Vec3 u(u01(0), u01(1), -u01(0) - u01(1));
  Vec3 m = n.cwiseProduct(Vec3(std::exp(u(0)), std::exp(u(1)), std::exp(u(2))));
  return m * (n.sum() / m.sum());
}

// With 3 % slack: a fitted tensor of a flat body sits on the boundary and noise may push it
// just across; a measured nominal (the racquet) may start 2 % beyond it.
bool triangle_holds(const Vec3& m) {
  const double slack = 0.03 * m.sum();
  return m(0) <= m(1) + m(2) + slack && m(1) <= m(0) + m(2) + slack && m(2) <= m(0) + m(1) + slack;
}

double tolerance(double, double) { return 0.03; }  // 3 % of a moment ratio

void apply(const Eigen::VectorXd& theta, const NominalInertia& nominal, ModelTerms& terms) {
  const Eigen::Matrix3d r = nominal.principal_axes.toRotationMatrix();
  terms.inertia = r * moments_of(nominal, theta).asDiagonal() * r.transpose();
}

EffectParameters parameters(const Eigen::VectorXd& theta, const NominalInertia& nominal, double) {
  EffectParameters p;
  p.principal_kg_m2 = moments_of(nominal, theta);
  describe_inertia(p, p.principal_kg_m2, nominal.principal_axes.toRotationMatrix(), nominal);
  return p;
}

// Every moment within 0.5 % of nominal.
std::string too_small(const EffectParameters& p, const SignificanceScale& scale) {
  if (scale.nominal == nullptr) return {};
  const double change =
      (p.principal_kg_m2.cwiseQuotient(scale.nominal->principal_moments).array() - 1.0).abs().maxCoeff();
  if (change < 0.005)
    return printf_text("its moments differ from nominal by at most %.2g %%", 100.0 * change);
  return {};
}

// Judged on the moments this candidate adds (an effect already in the model was judged
// when it joined).
std::string unphysical(const FittedSlice& fit) {
  if (fit.added == nullptr || triangle_holds(fit.added->principal_kg_m2)) return {};
  return "unphysical: fitted moments break the triangle inequality";
}

}  // namespace

constexpr EffectDescriptor inertia_moments_effect = [] {
  EffectDescriptor d;
  d.name = "inertia_moments";
  d.parameter_count = 2;
  d.sets_tensor = true;
  d.hooks = {tolerance, apply, parameters, too_small, no_objection, unphysical};
  return d;
}();

}  // namespace aloft::host::diagnose
