// One fit of the fitter (effect_fit.hpp) posed as a least-squares problem
// (levenberg_marquardt.hpp): its residuals and Jacobian, its options, its flights'
// starting rates, and the EffectFit its solution makes. Inside the fitter only.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/3_fit/effect_fit_result.hpp"
#include "diagnose/3_fit/fit_setup.hpp"
#include "diagnose/3_fit/flight_data.hpp"
#include "diagnose/3_fit/levenberg_marquardt.hpp"

namespace aloft::host::diagnose {

// The initial rate guess at sample `ref`: the nominal fit's rate there if there is one,
// else the mean of the usable readings within two samples of it.
Eigen::Vector3d starting_rate(const FlightData& data, std::size_t ref, const EffectFit* nominal_fit,
                              std::size_t index, const NominalInertia& nominal);

// A flight's local block: `rate`, then, where each flight has parameters of its own
// (FitSetup::own), those nearest `theta` (a whole theta; else zeros).
Eigen::VectorXd with_own(const FitSetup& setup, const Eigen::Vector3d& rate, const Eigen::VectorXd& theta);

// Each flight's theta in `fit` (FlightState::theta) from the shared parameters (the leading
// ones of `shared`) and its own, and fit.theta the first flight's; nothing where the
// flights share every parameter.
void set_flight_thetas(const FitSetup& setup, const Eigen::VectorXd& shared, EffectFit& fit);

// The least-squares problem of `setup`'s flights with `shared_count` effect parameters
// (of which each flight's own are moved to its local block, FitSetup::own)
// (flight_jacobian.hpp gives its Jacobian where it can); `setup` must outlive it.
ArrowProblem problem_of(const FitSetup& setup, int shared_count);

// The EffectFit of `setup` at `solution`: parameters, rates, cost, errors, and the
// linearisation at the solution where the fitter kept it.
EffectFit result_of(const FitSetup& setup, const LeastSquaresResult& solution, int shared_count);

// A fit's options: a single flight's fit without an impulse keeps its residuals and
// Jacobian at the solution (EffectFit::linearisation); an impulse's columns need the
// rate at the jump as well, which the fitter does not keep.
LeastSquaresOptions solution_options(const FitSetup& setup);

// Each flight's starting rate: the guess of starting_rate, refined with `theta` held by
// the separatrix-safe initial-state fit (initial_state_fit.hpp). The rotor of internal
// damping has no neutral theta, so its flights start from the rigid body's rates.
std::vector<Eigen::VectorXd> starting_rates(const FitSetup& setup, const EffectFit* nominal_fit,
                                            const Eigen::VectorXd& theta);

// Each flight's rate at its reference sample as the gyro reads it there (the mean of the
// usable readings within two samples): a start of a grid away from the nominal model has no
// fitted rate, and the nominal fit's rate suits the nominal moments only.
std::vector<Eigen::VectorXd> rates_read_at_reference(const FitSetup& setup);

}  // namespace aloft::host::diagnose
