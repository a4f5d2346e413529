// `inertia_moments`: the principal moments are wrong. theta = (u0, u1): moments
// n_i exp(u_i) (u2 = -u0-u1) along the nominal principal axes, rescaled to the nominal
// sum (gyro data and the torque-free equations cannot fix the scale).
#include <algorithm>
#include <cmath>
#include <vector>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "common/printf_text.hpp"

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

// theta of one principal moment scaled by `factor` (the other two kept), before the
// rescaling to the nominal sum: exp(u) is proportional to (factor, 1, 1) permuted.
Eigen::VectorXd one_moment_scaled(int axis, double factor) {
  Eigen::Vector3d u = Eigen::Vector3d::Zero();
  u(axis) = std::log(factor);
  u.array() -= u.sum() / 3.0;
  return u.head<2>();
}

// The factors a start grid scales one moment by, each up and down: a nominal's moment
// wrong by a factor of two or four (a missing or misplaced part, a wrong density; T06's
// Iy x4). Scaling one moment down is scaling the other two up, so the starts are two
// hexagonal rings around zero in the plane of u, their spacing ln 2 (a 2x change).
constexpr double kScaleFactors[] = {2.0, 4.0};

// The moments enter the torque-free equations non-linearly, and a fit from the nominal
// can stop in another basin (practice3/T06 flight 3: u = (0.740, -0.626), cost 1.99e6 on
// 91 samples, where (0.924, -0.462) reaches 1,186). Zero first, so that a flight whose
// nominal is right, or barely informs the moments, starts where it did without the grid.
std::vector<Eigen::VectorXd> scaled_moments() {
  std::vector<Eigen::VectorXd> starts{Eigen::VectorXd::Zero(2)};
  for (double factor : kScaleFactors) {
    for (int axis = 0; axis < 3; ++axis) {
      starts.push_back(one_moment_scaled(axis, factor));
      starts.push_back(one_moment_scaled(axis, 1.0 / factor));
    }
  }
  return starts;
}

// Joining a model: the nominal moments, as without a grid.
Eigen::VectorXd nominal_moments() { return Eigen::VectorXd::Zero(2); }

// Two fitted moment sets are other minima when a log ratio differs by more than 0.1 (a
// moment ratio 10 % apart, three times the tolerance).
constexpr StartGrid kMomentGrid{scaled_moments, 0.1, nominal_moments};

}  // namespace

constexpr EffectDescriptor inertia_moments_effect = [] {
  EffectDescriptor d;
  d.name = "inertia_moments";
  d.parameter_count = 2;
  d.sets_tensor = true;
  d.start_grid = &kMomentGrid;
  d.hooks = {tolerance, apply, parameters, too_small, no_objection, unphysical};
  return d;
}();

}  // namespace aloft::host::diagnose
