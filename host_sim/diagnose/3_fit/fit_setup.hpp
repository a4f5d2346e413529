// What one fit of the fitter (effect_fit.hpp) is of: the effect, its base, the flights and
// their reference samples; and the weighted residuals of a prediction on the samples a
// fit compares. Inside the fitter only.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

#include "diagnose/2_model/effect.hpp"
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
};

// The weighted residuals, every sample written once (no clearing first). Read through
// plain pointers: writing r through Eigen's made the compiler reload every vector's data
// at each sample (case00: 35.4 -> 26.7 M instructions here, the same arithmetic).
void residuals_of(const FlightData& data, const std::vector<Eigen::Vector3d>& readings, Eigen::VectorXd& r);

// The samples whose readings residuals_of reads: the compared ones.
inline ReadSamples compared_samples(const FlightData& d) { return {d.mask.data(), d.flight->usable.data()}; }

}  // namespace aloft::host::diagnose
