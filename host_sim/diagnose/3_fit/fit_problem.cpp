#include "diagnose/3_fit/fit_problem.hpp"

#include <algorithm>
#include <memory>
#include <utility>

#include "common/parallel_for.hpp"
#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/3_fit/flight_jacobian.hpp"
#include "diagnose/3_fit/initial_state_fit.hpp"
#include "diagnose/3_fit/parameter_errors.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

}  // namespace

Vec3 starting_rate(const FlightData& data, std::size_t ref, const EffectFit* nominal_fit, std::size_t index,
                   const NominalInertia& nominal) {
  const Flight& flight = *data.flight;
  if (nominal_fit != nullptr && index < nominal_fit->flights.size()) {
    std::vector<Vec3> readings;
    predict(*nominal_fit, nominal, index, flight, readings);
    return body_rate_of_reading(flight, readings[ref]);
  }
  Vec3 sum = Vec3::Zero();
  int count = 0;
  const std::size_t lo = ref >= 2 ? ref - 2 : 0;
  const std::size_t hi = std::min(flight.size(), ref + 3);
  for (std::size_t k = lo; k < hi; ++k) {
    if (flight.usable[k]) {
      sum += flight.omega[k];
      ++count;
    }
  }
  return body_rate_of_reading(flight, count > 0 ? Vec3(sum / count) : flight.omega[ref]);
}

ArrowProblem problem_of(const FitSetup& setup, int shared_count) {
  ArrowProblem problem;
  problem.shared_count = shared_count;
  problem.local_count = 3;
  problem.block_count = static_cast<int>(setup.data->size());
  problem.threads = setup.threads;
  problem.residuals = [&setup](int block, const Eigen::VectorXd& shared, const Eigen::VectorXd& local,
                               Eigen::VectorXd& r) {
    const FlightData& d = (*setup.data)[static_cast<std::size_t>(block)];
    const EffectModel model = setup.model();
    std::vector<Vec3> readings;
    predict_readings(model, *d.flight, setup.refs[static_cast<std::size_t>(block)], Vec3(local), shared,
                     readings, SampleStepping::shared_steps, nullptr, compared_samples(d));
    residuals_of(d, readings, r);
  };
  problem.jacobian = [&setup](int block, const Eigen::VectorXd& shared, const Eigen::VectorXd& local,
                              Eigen::VectorXd& r, Eigen::MatrixXd& jacobian) {
    return flight_jacobian(setup, block, shared, local, r, jacobian);
  };
  return problem;
}

EffectFit result_of(const FitSetup& setup, const LeastSquaresResult& solution, int shared_count) {
  EffectFit fit;
  fit.effect = setup.effect;
  fit.base = setup.base;
  fit.theta = solution.shared;
  fit.cost = solution.cost;
  fit.residual_count = 0;
  for (std::size_t i = 0; i < setup.data->size(); ++i) {
    FlightState state;
    state.ref = setup.refs[i];
    state.omega_ref = Vec3(solution.local[i]);
    state.impulse_time_s = setup.impulse_time_s;
    fit.flights.push_back(state);
    fit.residual_count += (*setup.data)[i].residual_count();
  }
  const int parameters = shared_count + 3 * static_cast<int>(setup.data->size());
  const int dof = std::max(1, fit.residual_count - parameters);
  ParameterErrors errors =
      parameter_errors(solution.normal_matrix, shared_count, 3, std::max(fit.cost / dof, 1e-12));
  fit.theta_standard_error = std::move(errors.standard_error);
  fit.theta_covariance = std::move(errors.covariance);
  if (solution.block_jacobians.size() == 1) {
    auto kept = std::make_shared<SolutionLinearisation>();
    kept->data = (*setup.data)[0];
    kept->impulse_time_s = setup.impulse_time_s;
    kept->theta = solution.shared;
    kept->omega_ref = solution.local[0];
    kept->residuals = solution.block_residuals[0];
    kept->jacobian = solution.block_jacobians[0];
    fit.linearisation = std::move(kept);
  }
  return fit;
}
LeastSquaresOptions solution_options(const FitSetup& setup) {
  LeastSquaresOptions options;
  options.keep_jacobian = setup.data->size() == 1 && !has_searched_time(setup.model());
  return options;
}
std::vector<Eigen::VectorXd> starting_rates(const FitSetup& setup, const EffectFit* nominal_fit,
                                            const Eigen::VectorXd& theta) {
  const bool rigid = !describe(setup.effect).neutral_at_zero;
  const EffectModel model{rigid ? Effect::none : setup.effect, *setup.nominal, setup.impulse_time_s,
                          setup.base};
  const Eigen::VectorXd held = rigid ? Eigen::VectorXd(theta.head(model_parameter_count(model))) : theta;
  // At theta = 0 every effect is the nominal model, whose fitted rates are already the
  // answer: nothing to refine (never so for a compound model: its base is fitted).
  const bool nominal_model = nominal_fit != nullptr && setup.base.empty() && (rigid || theta.isZero());
  std::vector<Eigen::VectorXd> rates(setup.data->size());
  const auto rate_of = [&](std::size_t i) {
    const Vec3 guess = starting_rate((*setup.data)[i], setup.refs[i], nominal_fit, i, *setup.nominal);
    rates[i] = nominal_model
                   ? guess
                   : fit_initial_state(model, (*setup.data)[i], setup.refs[i], held, &guess).omega_ref;
  };
  if (setup.threads > 1 && rates.size() > 1) {
    parallel_for(rates.size(), setup.threads, rate_of);
  } else {
    for (std::size_t i = 0; i < rates.size(); ++i) rate_of(i);
  }
  return rates;
}
std::vector<Eigen::VectorXd> rates_read_at_reference(const FitSetup& setup) {
  std::vector<Eigen::VectorXd> rates;
  for (std::size_t i = 0; i < setup.data->size(); ++i) {
    rates.emplace_back(starting_rate((*setup.data)[i], setup.refs[i], nullptr, i, *setup.nominal));
  }
  return rates;
}

}  // namespace aloft::host::diagnose
