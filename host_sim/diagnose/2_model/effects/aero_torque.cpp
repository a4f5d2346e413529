// `aero_torque`: aerodynamic damping, tau = -k |w| w. theta = p = k / I_mean (1/rad).
#include <algorithm>
#include <cmath>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "common/printf_text.hpp"

namespace aloft::host::diagnose {
namespace {

double mean_moment(const NominalInertia& nominal) { return nominal.tensor.trace() / 3.0; }

// k = p I_mean, written as (p trace) / 3 (the fitter's rounding, kept).
double k_of(const Eigen::VectorXd& theta, const NominalInertia& nominal) {
  return theta(0) * nominal.tensor.trace() / 3.0;
}

// A drag that changes |w| by 1 % over the flight.
double tolerance(double mean_speed, double duration_s) {
  return 0.01 / std::max(mean_speed * duration_s, 1e-6);
}

void apply(const Eigen::VectorXd& theta, const NominalInertia& nominal, ModelTerms& terms) {
  terms.drag = k_of(theta, nominal);
}

EffectParameters parameters(const Eigen::VectorXd& theta, const NominalInertia& nominal, double) {
  EffectParameters p;
  p.k_N_m_s2 = k_of(theta, nominal);
  return p;
}

// |w| would fall by less than 0.5 % over the data.
std::string too_small(const EffectParameters& p, const SignificanceScale& scale) {
  if (scale.nominal == nullptr) return {};
  const double fall = std::abs(p.k_N_m_s2) / mean_moment(*scale.nominal) * scale.speed * scale.duration_s;
  if (fall < 0.005) return printf_text("|w| would fall by only %.2g %%", 100.0 * fall);
  return {};
}

// A drag that feeds energy in, beyond three standard errors (wherever it is in the model).
std::string unphysical(const FittedSlice& fit) {
  if (fit.theta.size() < 1 || fit.standard_error.size() < 1) return {};
  const double se = fit.standard_error(0);
  const double k = fit.theta(0);
  if (!(k < 0 && k < -3.0 * (std::isfinite(se) ? se : 0.0))) return {};
  return "unphysical: negative drag (energy gain)";
}

}  // namespace

constexpr EffectDescriptor aero_torque_effect = [] {
  EffectDescriptor d;
  d.name = "aero_torque";
  d.parameter_count = 1;
  d.hooks = {tolerance, apply, parameters, too_small, no_objection, unphysical};
  return d;
}();

}  // namespace aloft::host::diagnose
