// The tensor report's intervals (tensor_report.hpp) from a judged analysis.
//
// How the intervals are made (docs/diagnose.md, "Is my tensor right?", argues the choice):
// - The ratios come from the inertia_moments candidate (or, where the verdict holds a
//   rotor, from the moments fitted beside it: tensor_intervals.cpp, moments_fit), whose
//   parameters are log moments,
//   so a log ratio is linear in them and its error follows from theirs exactly.
// - One flight: the fit's own covariance (noise taken from the residuals, cost/dof), widened
//   for the residuals' serial correlation (a low-passed gyro's noise is not white): the
//   variance is multiplied by (1 + rho) / (1 - rho), rho the lag-1 autocorrelation of the
//   held-out residuals.
// - A session: a jackknife over flights (the leave-one-flight-out fits the pooled analysis
//   makes anyway), with Student's t on n - 1 degrees of freedom so that few flights give
//   wide intervals; never narrower than the one-fit error above. Flights that disagree
//   beyond their noise widen it, which a fit's own covariance would hide.
#pragma once

#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/4_judge/analysis.hpp"
#include "diagnose/4_judge/tensor_report.hpp"

namespace aloft::host::diagnose {

// How much serial correlation of the held-out residuals of candidate `c` (fitted on
// `flights`) inflates a variance: the AR(1) factor (1 + rho) / (1 - rho), rho the lag-1
// autocorrelation over the flights' usable samples, clamped to [0, 0.95].
double serial_inflation(const Candidate& c, const std::vector<const Flight*>& flights);

// One flight's report from its analysis (its inertia_moments and inertia_axes candidates).
// None when the analysis has no inertia_moments fit.
bool flight_tensor_report(const Analysis& analysis, const std::vector<const Flight*>& flights,
                          const NominalInertia& nominal, TensorReport& report);

// The pooled report of a session: jackknife over the flights' leave-one-out fits.
bool pooled_tensor_report(const Analysis& pooled, const std::vector<const Flight*>& flights,
                          const NominalInertia& nominal, TensorReport& report);

}  // namespace aloft::host::diagnose
