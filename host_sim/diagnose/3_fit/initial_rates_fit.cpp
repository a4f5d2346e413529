#include "diagnose/3_fit/initial_rates_fit.hpp"

#include <algorithm>

#include "diagnose/3_fit/fit_problem.hpp"
#include "diagnose/3_fit/fit_setup.hpp"
#include "diagnose/3_fit/levenberg_marquardt.hpp"

namespace aloft::host::diagnose {
namespace {

// `problem` with the effect parameters held at `theta`: only the rates are fitted.
ArrowProblem rates_only(const ArrowProblem& problem, const Eigen::VectorXd& theta) {
  ArrowProblem held = problem;
  held.residuals = [&problem, theta](int block, const Eigen::VectorXd&, const Eigen::VectorXd& local,
                                     Eigen::VectorXd& r) { problem.residuals(block, theta, local, r); };
  held.jacobian = nullptr;  // only the rates are fitted: no sensor column to read off
  return held;
}

// The rates of `setup`'s flights fitted from `starts` with the effect parameters of `fixed`
// held.
EffectFit rates_fitted_from(const FitSetup& setup, const EffectFit& fixed,
                            const std::vector<Eigen::VectorXd>& starts) {
  const ArrowProblem problem = problem_of(setup, 0);
  LeastSquaresOptions options;
  options.normal_at_solution = false;  // no effect parameter to give an error for
  const LeastSquaresResult solution =
      minimise(rates_only(problem, fixed.theta), Eigen::VectorXd(), starts, options);
  EffectFit fit = result_of(setup, solution, 0);
  set_flight_thetas(setup, fixed.theta, fit);
  fit.theta = fixed.theta;
  fit.theta_standard_error = fixed.theta_standard_error;
  return fit;
}

FitSetup rates_setup(const EffectFit& fixed, const NominalInertia& nominal,
                     const std::vector<FlightData>& data) {
  FitSetup setup{fixed.effect, &nominal, &data, {}, 0.0, fixed.base, Eigen::VectorXd()};
  for (const FlightData& d : data) {
    setup.refs.push_back(compound_reference_index(setup.model(), *d.flight));
  }
  return setup;
}

}  // namespace

EffectFit fit_initial_rates(const EffectFit& fixed, const NominalInertia& nominal,
                            const std::vector<FlightData>& data, const EffectFit* nominal_fit) {
  const FitSetup setup = rates_setup(fixed, nominal, data);
  return rates_fitted_from(setup, fixed, starting_rates(setup, nominal_fit, fixed.theta));
}

EffectFit fit_initial_rates_near(const EffectFit& fixed, const NominalInertia& nominal,
                                 const FlightData& data, const EffectFit& near, std::size_t index,
                                 const EffectFit* nominal_fit) {
  const std::vector<FlightData> flights{data};
  const FitSetup setup = rates_setup(fixed, nominal, flights);
  if (index >= near.flights.size() || near.flights[index].ref != setup.refs[0] ||
      near.theta.size() != fixed.theta.size() || local_of(near, index).size() != setup.local_count()) {
    return fit_initial_rates(fixed, nominal, flights, nominal_fit);
  }
  const std::vector<Eigen::VectorXd> start{local_of(near, index)};
  EffectFit cheap = rates_fitted_from(setup, fixed, start);
  const ArrowProblem problem = problem_of(setup, 0);
  const double reference = cost_at(rates_only(problem, near.theta), Eigen::VectorXd(), start);
  const bool kept = cheap.cost <= kNearRateCostRatio * reference &&
                    cheap.cost <= kNearRateMaxMisfit * std::max(cheap.residual_count, 1);
  if (kept) return cheap;
  EffectFit safe = fit_initial_rates(fixed, nominal, flights, nominal_fit);
  return cheap.cost < safe.cost ? cheap : safe;
}

}  // namespace aloft::host::diagnose
