// Fitting one candidate effect to one or more flights: the effect's parameters (shared by
// every flight given) and each flight's initial rate, by weighted least squares on the
// samples a mask lets through. Residuals are (predicted - measured) / sigma per axis, so
// the cost is a chi-square when sigma is the noise floor.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/2_model/effect.hpp"
#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/flight_model.hpp"
#include "diagnose/3_fit/flight_data.hpp"

namespace aloft::host::diagnose {

struct FlightState {
  std::size_t ref = 0;  // sample whose body rate is omega_ref
  Eigen::Vector3d omega_ref = Eigen::Vector3d::Zero();
  double impulse_time_s = 0.0;  // impulse only
};

// Another minimum of a searched parameter (the impulse time, the damping rotor's start),
// refined as the chosen one is: its parameters, impulse time and training cost. Of two
// refined minima the search keeps the lower; the judging (4_judge/confidence.hpp,
// kCloseMinimum) says whether the other is close enough to report.
struct OtherMinimum {
  Eigen::VectorXd theta;
  double impulse_time_s = 0.0;
  double cost = 0.0;
};

// A search refines another minimum only when a quick fit there came within this much of
// the chosen one's cost (chi-square; or this share of that cost on data whose misfit
// exceeds the noise): a budget, not a judgement.
constexpr double kOtherMinimumWindow = 50.0;
constexpr double kOtherMinimumWindowShare = 0.05;

// fit_initial_rates_near: how far the refit of a fold's rate from the all-samples fit's
// rate may end before the separatrix-safe start is tried too: at most this many times the
// all-samples fit's cost on the fold's samples, and at most this misfit (chi-square per
// residual). Measured with both refits made on every left-out fold of the diagnose,
// session, phone and rotor tests (9,502 folds) and of a 10-flight aero_torque log (340):
// where the refit from the all-samples rate ended more than 1e-5 above the safe one (36
// folds, by up to 2,400 times: a candidate that misses the flight by far, whose rate the
// pooled fit cannot guide), its misfit was 622 per residual or more. Of the tests' folds
// these bounds keep 5,718, each within 4e-6 of the safe fit's cost; on the log it ended
// at the safe fit's cost on every fold, at up to 2.07 times the all-samples cost (a wrong
// effect fitted without the flight) and up to 444 per residual.
constexpr double kNearRateCostRatio = 3.0;
constexpr double kNearRateMaxMisfit = 300.0;

struct SolutionLinearisation;

struct EffectFit {
  Effect effect = Effect::none;
  std::vector<Effect> base;  // a compound model: effects fitted with `effect` (flight_model.hpp)
  Eigen::VectorXd theta;     // effect parameters, shared by the flights (see flight_model.hpp)
  std::vector<FlightState> flights;
  double cost = 0.0;       // weighted sum of squared training residuals
  int residual_count = 0;  // training residuals (3 per sample)
  // Standard errors of theta from cost/dof * (J^T J)^-1 (initial rates marginalised);
  // infinite where the data does not inform a parameter.
  Eigen::VectorXd theta_standard_error;
  // The same errors' full covariance (uninformed directions left out: their variance is
  // not bounded by the data).
  Eigen::MatrixXd theta_covariance;
  std::vector<OtherMinimum> other_minima;  // searched effects only
  // A fit of one flight without an impulse: its residuals and Jacobian at the solution,
  // from the fit's last iteration, for its folds' steps (SharedLinearisation); null
  // otherwise, or once they are no longer wanted.
  std::shared_ptr<const SolutionLinearisation> linearisation;
};

// The model of `fit` for flight `index` (impulse time included).
EffectModel model_of(const EffectFit& fit, const NominalInertia& nominal, std::size_t index);

// Predicted readings of flight `index` under `fit`.
void predict(const EffectFit& fit, const NominalInertia& nominal, std::size_t index, const Flight& flight,
             std::vector<Eigen::Vector3d>& readings);

// Fits `effect` to `data`. `nominal_fit`, the `none` fit of the same data, gives the
// starting rates (nullptr: start from the readings themselves). An impulse belongs to one
// flight: fitting it to several flights at once is refused (std::invalid_argument).
// `theta_start` (optional) starts the effect parameters elsewhere than at nominal.
// `threads`: the flights of a pooled fit are evaluated on up to this many threads (the
// result is the same whatever the count).
EffectFit fit_effect(Effect effect, const NominalInertia& nominal, const std::vector<FlightData>& data,
                     const EffectFit* nominal_fit, const Eigen::VectorXd* theta_start = nullptr,
                     unsigned threads = 1);

// Fits the effects of `base` (a fit of the same data) with `added` jointly: a compound
// model, the next step of a stepwise selection (stepwise_selection.hpp). The base
// parameters start at their fitted values, the added ones at zero (or `theta_start`, the
// whole compound theta); the rates start at the base fit's. An impulse in the base keeps
// its fitted time; an added impulse is searched about the base model. `threads` as for
// fit_effect. A fit from `theta_start` is also tried from the added effect's start read off
// the readings (its base part from theta_start) where `readings_start_when_seeded` and that
// start costs less than where it ended: a flight's own fit seeded from a pooled one
// (5_flow/flights_left_out.cpp).
EffectFit fit_added_effect(const EffectFit& base, Effect added, const NominalInertia& nominal,
                           const std::vector<FlightData>& data, const Eigen::VectorXd* theta_start = nullptr,
                           unsigned threads = 1, bool readings_start_when_seeded = false);

// One flight's weighted residuals and their Jacobian [theta | omega_ref] at a fit's
// solution, made over the samples of `data` as refit_from_solution's step makes them, for
// the folds of the flight to share: a fold's are these with the rows it does not compare
// zeroed (a differenced column's row there is (0 - 0) / h, a sensor column's is zeroed,
// both +0; the impulse's columns are made again from the zeroed rate columns, as the
// fold's own step makes them). Two folds then cost one Jacobian instead of two (case00:
// the folds' steps were 33 M of its 405 M instructions; 405.0 -> 394.0 M), and none
// where the fit kept its own (EffectFit::linearisation; 394.0 -> 380.8 M).
struct SolutionLinearisation {
  FlightData data;  // the samples it was made over
  double impulse_time_s = 0.0;
  Eigen::VectorXd theta, omega_ref;  // the point
  Eigen::VectorXd residuals;
  Eigen::MatrixXd jacobian;
  Eigen::Matrix3d impulse_rate_derivative = Eigen::Matrix3d::Identity();  // d rate at the jump / d omega_ref
};
SolutionLinearisation linearise_at_solution(const EffectFit& fit, const NominalInertia& nominal,
                                            const FlightData& data, double impulse_time_s);

// The fit's own linearisation (EffectFit::linearisation) where it kept one, else
// linearise_at_solution of the fit over `data`, made when a fold first asks for it and
// then kept for the other fold. All three must outlive it.
class SharedLinearisation {
 public:
  SharedLinearisation(const EffectFit& fit, const NominalInertia& nominal, const FlightData& data)
      : fit_(fit), nominal_(nominal), data_(data) {}
  // At the fit's solution with the impulse at `impulse_time_s`: nullptr where it was made
  // for another time already (the fold then makes its own).
  const SolutionLinearisation* at(double impulse_time_s) {
    if (fit_.linearisation != nullptr && fit_.linearisation->impulse_time_s == impulse_time_s) {
      return fit_.linearisation.get();  // the fit's own last iteration made it
    }
    if (!made_) made_ = linearise_at_solution(fit_, nominal_, data_, impulse_time_s);
    return made_->impulse_time_s == impulse_time_s ? &*made_ : nullptr;
  }

 private:
  const EffectFit& fit_;
  const NominalInertia& nominal_;
  const FlightData& data_;
  std::optional<SolutionLinearisation> made_;
};

// `fit`, a fit of one flight to all its samples, refitted to the samples of `data` (a
// fold's training samples) by one Gauss-Newton step from its own solution
// (levenberg_marquardt.hpp, gauss_newton_step), the impulse (if the model has one) at
// `impulse_time_s`. From the all-samples solution that step reaches the fold's own
// solution to first order, so the samples the fold leaves out do not steer its parameters
// to that order: their prediction is still held out. It costs one Jacobian and a
// simulation or two, where a refit from the same start took ten to forty iterations.
//
// `at_solution` (optional): linearise_at_solution of the same fit and impulse time over
// samples that include every one `data` compares; the step then takes its residuals and
// Jacobian from it, with the rows `data` leaves out zeroed, instead of making its own:
// the same numbers bit for bit (see linearise_at_solution).
EffectFit refit_from_solution(const EffectFit& fit, const NominalInertia& nominal, const FlightData& data,
                              double impulse_time_s, const SolutionLinearisation* at_solution = nullptr);

// The effect parameters without each flight in turn (one Gauss-Newton step from `fit`, the
// all-flights solution; levenberg_marquardt.hpp), the flights on up to `threads` threads.
// Not for impulses.
std::vector<Eigen::VectorXd> leave_one_flight_out(const EffectFit& fit, const NominalInertia& nominal,
                                                  const std::vector<FlightData>& data, unsigned threads = 1);

// Refits only the flights' initial rates with the effect parameters of `fixed` held: how a
// fitted effect is carried over to a flight it never saw.
EffectFit fit_initial_rates(const EffectFit& fixed, const NominalInertia& nominal,
                            const std::vector<FlightData>& data, const EffectFit* nominal_fit);

// A fold's refit of one flight's initial rate (fit_initial_rates, `data` one flight)
// where the rate is already known near here: `near` is a fit of all of this flight's
// samples (flight `index` of it), with effect parameters close to `fixed`'s (a pooled fit,
// `fixed` the same effect without this flight). The rate-only fit starts from near's rate,
// skipping the separatrix-safe start (initial_state_fit.hpp) that costs twice the fit
// itself. It is kept when it explains the fold's samples about as well as `near` does
// (its cost at most kNearRateCostRatio times near's cost on them) and near the noise
// (kNearRateMaxMisfit): a start in the basin of a wrong motion cannot. Otherwise the
// separatrix-safe fit is made too and the lower of the two kept.
EffectFit fit_initial_rates_near(const EffectFit& fixed, const NominalInertia& nominal,
                                 const FlightData& data, const EffectFit& near, std::size_t index,
                                 const EffectFit* nominal_fit);

// Weighted sum of squared residuals of `readings` on the masked samples, and their count.
double weighted_squares(const FlightData& data, const std::vector<Eigen::Vector3d>& readings,
                        int* residual_count = nullptr);

}  // namespace aloft::host::diagnose
