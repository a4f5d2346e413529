// What a fit of a candidate effect gives (effect_fit.hpp makes it): the effect's
// parameters, shared by the flights fitted, each flight's initial state, the cost and the
// parameters' errors, another minimum a search found, and the residuals and Jacobian at
// the solution where the fit kept them; and the model and readings it stands for.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <memory>
#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/effect.hpp"
#include "diagnose/2_model/flight_model.hpp"
#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/3_fit/flight_data.hpp"

namespace aloft::host::diagnose {

struct FlightState {
  std::size_t ref = 0;  // sample whose body rate is omega_ref
  Eigen::Vector3d omega_ref = Eigen::Vector3d::Zero();
  double impulse_time_s = 0.0;  // impulse only
  // Its own effect parameters in a pooled fit (FlightOwnParameters; empty: none), and the
  // theta they make with the shared ones: what the flight is predicted with.
  Eigen::VectorXd own, theta;
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

struct SolutionLinearisation;

struct EffectFit {
  Effect effect = Effect::none;
  std::vector<Effect> base;  // a compound model: effects fitted with `effect` (flight_model.hpp)
  // Effect parameters, shared by the flights (see flight_model.hpp); where each flight has
  // parameters of its own (FlightState::own), the first flight's theta, whose leading
  // entries are the shared ones.
  Eigen::VectorXd theta;
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

// The model of `fit` for flight `index` (impulse time included).
EffectModel model_of(const EffectFit& fit, const NominalInertia& nominal, std::size_t index);

// The theta flight `index` of `fit` is predicted with.
const Eigen::VectorXd& flight_theta(const EffectFit& fit, std::size_t index);

// Flight `index`'s local block of the fit: its rate, then its own parameters.
Eigen::VectorXd local_of(const EffectFit& fit, std::size_t index);

// Predicted readings of flight `index` under `fit`.
void predict(const EffectFit& fit, const NominalInertia& nominal, std::size_t index, const Flight& flight,
             std::vector<Eigen::Vector3d>& readings);

// Weighted sum of squared residuals of `readings` on the masked samples, and their count.
double weighted_squares(const FlightData& data, const std::vector<Eigen::Vector3d>& readings,
                        int* residual_count = nullptr);

}  // namespace aloft::host::diagnose
