// What one fit of the fitter (effect_fit.hpp) is of: the effect, its base, the flights and
// their reference samples; and the weighted residuals of a prediction on the samples a
// fit compares. Inside the fitter only.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

#include "diagnose/2_model/effect.hpp"
#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/2_model/flight_model.hpp"
#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/3_fit/flight_data.hpp"

namespace aloft::host::diagnose {

struct FitSetup {
  Effect effect;
  const NominalInertia* nominal;
  const std::vector<FlightData>* data;
  std::vector<std::size_t> refs;
  double impulse_time_s = 0.0;
  std::vector<Effect> base;    // compound: effects fitted jointly with `effect`
  Eigen::VectorXd base_theta;  // their fitted values (impulse scan, starting point)
  unsigned threads = 1;        // flights fitted concurrently (a pooled fit)

  EffectModel model() const { return EffectModel{effect, *nominal, impulse_time_s, base}; }

  // Each flight's own parameters beside its rate (descriptor `flight_own`; the effect
  // alone), null where the flights share every parameter.
  const FlightOwnParameters* own() const;
  // Entries of each flight's local block: its rate, then its own parameters.
  int local_count() const;
  // The parameters the pooled fit shares, of a model with `model_count` (theta's whole
  // parameterisation, or 0 where they are held).
  int shared_count(int model_count) const;
  // The theta flight `block` is predicted with: the shared parameters (the leading ones of
  // `shared` where it holds a whole theta) with the flight's own from `local`.
  Eigen::VectorXd block_theta(const Eigen::VectorXd& shared, const Eigen::VectorXd& local) const;
};

// The first flight's scale of the shared part (FlightOwnParameters) is pinned at 0 by a
// residual of this weight: the data do not see it (the shared part moves with it), so it
// costs nothing there, and at 1e4 its variance leaves the shared part's errors alone
// (1e-8 of their square).
constexpr double kPinnedScaleWeight = 1e4;

// The weighted residuals, every sample written once (no clearing first). Read through
// plain pointers: writing r through Eigen's made the compiler reload every vector's data
// at each sample (case00: 35.4 -> 26.7 M instructions here, the same arithmetic).
void residuals_of(const FlightData& data, const std::vector<Eigen::Vector3d>& readings, Eigen::VectorXd& r);

// The samples whose readings residuals_of reads: the compared ones.
inline ReadSamples compared_samples(const FlightData& d) { return {d.mask.data(), d.flight->usable.data()}; }

}  // namespace aloft::host::diagnose
