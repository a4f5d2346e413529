#include "study/inertia_perturbation.hpp"

#include "common/body_file.hpp"

#include <boost/random/uniform_real_distribution.hpp>

#include <cmath>
#include <stdexcept>

namespace aloft::host {

const char* family_name(PerturbationFamily family) {
  switch (family) {
    case PerturbationFamily::moments: return "moments";
    case PerturbationFamily::axes: return "axes";
    case PerturbationFamily::both: return "both";
  }
  return "?";
}

const char* family_unit(PerturbationFamily family) {
  return family == PerturbationFamily::moments ? "%" : "deg";
}

const char* axes_sampler_name(AxesSampler sampler) {
  return sampler == AxesSampler::cardan ? "cardan" : "ball";
}

namespace {

Eigen::Vector3d uniform_in_unit_ball(SimulationRandom& random) {
  boost::random::uniform_real_distribution<double> u(-1.0, 1.0);
  for (;;) {
    const Eigen::Vector3d v(u(random), u(random), u(random));
    if (v.squaredNorm() <= 1.0) return v;
  }
}

// The rotation of the principal axes for one draw with bound `radians`.
Eigen::Quaterniond axes_rotation(AxesSampler sampler, double radians, SimulationRandom& random) {
  if (sampler == AxesSampler::ball) {
    return aloft::quat_exp(Eigen::Vector3d(radians * uniform_in_unit_ball(random)));
  }
  boost::random::uniform_real_distribution<double> u(-1.0, 1.0);
  const double a = radians * u(random), b = radians * u(random), c = radians * u(random);
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(b, Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(c, Eigen::Vector3d::UnitZ());
}

}  // namespace

InertiaTensor<double> draw_perturbed_inertia(const InertiaTensor<double>& nominal,
                                             const InertiaPerturbation& perturbation,
                                             SimulationRandom& random) {
  const bool moments = perturbation.family != PerturbationFamily::axes;
  const bool axes = perturbation.family != PerturbationFamily::moments;
  boost::random::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int attempt = 0; attempt < 1000; ++attempt) {
    // Every draw takes the same numbers from the stream whatever the family, so that
    // simulation i of every analysis sees the same unit perturbation, scaled by the bound.
    const Eigen::Vector3d unit_moments(u(random), u(random), u(random));
    const Eigen::Quaterniond rotation =
        axes_rotation(perturbation.sampler, perturbation.bound * M_PI / 180.0, random);
    Eigen::Vector3d principal = nominal.principal_moments();
    if (moments) {
      const double fraction = perturbation.bound / 100.0;
      principal = principal.cwiseProduct(Eigen::Vector3d::Ones() + fraction * unit_moments);
    }
    Eigen::Quaterniond principal_to_body = nominal.principal_axes();
    if (axes) principal_to_body = (rotation * principal_to_body).normalized();
    InertiaTensor<double> out;
    // Held to the same triangle slack as a measured body file: a flat body's nominal
    // moments may already sit just past the strict inequality.
    if (InertiaTensor<double>::make_from_principal(principal, principal_to_body, out,
                                                   kMeasuredTriangleSlack) == Status::ok) {
      return out;
    }
  }
  throw std::runtime_error("no valid inertia tensor within the perturbation bound");
}

}  // namespace aloft::host
