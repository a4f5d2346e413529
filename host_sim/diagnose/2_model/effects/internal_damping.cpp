// `internal_damping`: energy lost inside the body at constant |L|, modelled as a
// spherical rotor in a viscous cavity. theta = (a, b): rotor J = 0.9 I_min logistic(a),
// coupling c = J exp(b). The rotor co-rotates with the body at release, so the fitted
// initial rate is the first sample's; "no rotor" is a limit, not a point of theta.
#include <algorithm>
#include <cmath>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "common/printf_text.hpp"

namespace aloft::host::diagnose {
namespace {

// Rotor coupling rates above this are a rigid body for every flight we see; the cap keeps
// flight_dynamics.hpp's explicit steps (at most 5 ms) stable (c/J h < 2).
constexpr double kMaxRotorRate = 400.0;

double logistic(double a) { return 1.0 / (1.0 + std::exp(-a)); }

double rotor_of(const Eigen::VectorXd& theta, const NominalInertia& nominal) {
  return 0.9 * nominal.principal_moments(0) * logistic(theta(0));
}

double rotor_rate_of(const Eigen::VectorXd& theta) { return std::min(std::exp(theta(1)), kMaxRotorRate); }

double tolerance(double, double) { return 2.0; }  // log scales of rotor size and rate

void apply(const Eigen::VectorXd& theta, const NominalInertia& nominal, ModelTerms& terms) {
  terms.rotor = rotor_of(theta, nominal);
  terms.rotor_rate = rotor_rate_of(theta);
}

EffectParameters parameters(const Eigen::VectorXd& theta, const NominalInertia& nominal, double) {
  EffectParameters p;
  p.rotor_J_kg_m2 = rotor_of(theta, nominal);
  p.c_N_m_s = p.rotor_J_kg_m2 * rotor_rate_of(theta);
  return p;
}

// No bar of its own: the shrink of the held-out gap decides.
std::string too_small(const EffectParameters&, const SignificanceScale&) { return {}; }

// theta of a rotor of `fraction` of 0.9 I_min (the logistic's inverse) coupled at `rate`.
Eigen::VectorXd rotor_theta(double fraction, double rate) {
  Eigen::VectorXd theta(2);
  theta << std::log(fraction / 0.9 / (1.0 - fraction / 0.9)), std::log(rate);
  return theta;
}

// The rotor's size and coupling enter non-linearly, and "no rotor" is a limit, not a
// point: a small grid of plausible rotors, each costed with the rigid body's fitted
// initial rate; the refinement from the best then frees the rate (a tumbling flight's
// nominal fit can be far from the rate that suits a damped one).
std::vector<Eigen::VectorXd> plausible_rotors() {
  std::vector<Eigen::VectorXd> starts;
  for (double fraction : {0.03, 0.1, 0.3}) {
    for (double rate : {3.0, 10.0, 30.0, 100.0}) starts.push_back(rotor_theta(fraction, rate));
  }
  return starts;
}

// Joining a model: the grid's middle rotor.
Eigen::VectorXd middle_rotor() { return rotor_theta(0.1, 10.0); }

// Two rotors are other minima when their log-size or log-rate differ by more than this
// (a factor of two).
constexpr StartGrid kRotorGrid{plausible_rotors, 0.7, middle_rotor};

}  // namespace

constexpr EffectDescriptor internal_damping_effect = [] {
  EffectDescriptor d;
  d.name = "internal_damping";
  d.parameter_count = 2;
  d.starts_at_release = true;
  d.neutral_at_zero = false;
  d.start_grid = &kRotorGrid;
  d.hooks = {tolerance, apply, parameters, too_small, no_objection, no_physics_objection};
  return d;
}();

}  // namespace aloft::host::diagnose
