// The tensor report (SPEC §4 `tensor`): how well the data pin down the nominal tensor.
// Principal-moment ratios I2/I1 and I3/I1 in the body file's axis order, their 95 %
// intervals, the angle within which the principal axes are held, and whether the nominal
// ratios lie inside the intervals.
//
// How the intervals are made (docs/diagnose.md, "Is my tensor right?", argues the choice):
// - The ratios come from the inertia_moments candidate, whose parameters are log moments,
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

#include <Eigen/Core>

#include <string>
#include <vector>

#include "diagnose/nominal_inertia.hpp"

namespace aloft::host::diagnose {

struct Analysis;
struct Flight;

struct TensorReport {
  Eigen::Vector2d ratio_best = Eigen::Vector2d::Ones();  // I2/I1, I3/I1 (body file order)
  Eigen::Vector2d ratio_low = Eigen::Vector2d::Ones(), ratio_high = Eigen::Vector2d::Ones();
  Eigen::Vector2d ratio_nominal = Eigen::Vector2d::Ones();
  Eigen::Vector3i axis_order = Eigen::Vector3i(0, 1, 2);  // body axis b holds principal axis_order(b)
  double axes_95_deg = 0.0;
  bool axes_known = false;  // false: no axes fit to judge them by
  bool consistent_with_nominal = true;
  int flights = 1;
  std::string method;
};

// The nominal principal axis (index into the ascending moments) nearest each body axis.
Eigen::Vector3i principal_axis_order(const NominalInertia& nominal);

// One flight's report from its analysis (its inertia_moments and inertia_axes candidates).
// None when the analysis has no inertia_moments fit.
bool flight_tensor_report(const Analysis& analysis, const std::vector<const Flight*>& flights,
                          const NominalInertia& nominal, TensorReport& report);

// Sets analysis.tensor from the flight's report (when there is one) and tempers the
// verdict's confidence with it.
void attach_flight_tensor_report(Analysis& analysis, const Flight& flight, const NominalInertia& nominal);

// The pooled report of a session: jackknife over the flights' leave-one-out fits.
bool pooled_tensor_report(const Analysis& pooled, const std::vector<const Flight*>& flights,
                          const NominalInertia& nominal, TensorReport& report);

// A verdict is not confident when its held-out shrink is below kPracticalShrink, or when
// the tensor report (if any) finds the nominal ratios consistent with the data.
constexpr double kPracticalShrink = 0.10;
void temper_confidence(Analysis& analysis);

// "the 6 flights hold I2/I1 to 0.27 ± 0.01 ...": the line the summary leads with.
std::string tensor_summary(const TensorReport& report);

}  // namespace aloft::host::diagnose
