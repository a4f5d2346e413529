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

Eigen::VectorXd with_own(const FitSetup& setup, const Vec3& rate, const Eigen::VectorXd& theta) {
  const FlightOwnParameters* own = setup.own();
  if (own == nullptr) return rate;
  Eigen::VectorXd local(3 + own->count);
  const bool whole = theta.size() == effect_parameter_count(setup.effect);
  local << rate, whole ? own->own_of(theta, theta.head(own->shared_count))
                       : Eigen::VectorXd(Eigen::VectorXd::Zero(own->count));
  return local;
}

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
  problem.shared_count = setup.shared_count(shared_count);
  problem.local_count = setup.local_count();
  problem.block_count = static_cast<int>(setup.data->size());
  problem.threads = setup.threads;
  // Where each flight has parameters of its own, the first flight's scale is pinned while
  // the shared ones are fitted (FlightOwnParameters; held, every flight's scale is free).
  const bool pinned = setup.own() != nullptr && problem.shared_count > 0;
  problem.residuals = [&setup, pinned](int block, const Eigen::VectorXd& shared, const Eigen::VectorXd& local,
                                       Eigen::VectorXd& r) {
    const FlightData& d = (*setup.data)[static_cast<std::size_t>(block)];
    const EffectModel model = setup.model();
    std::vector<Vec3> readings;
    const bool own = setup.own() != nullptr;
    predict_readings(model, *d.flight, setup.refs[static_cast<std::size_t>(block)], Vec3(local.head<3>()),
                     own ? setup.block_theta(shared, local) : shared, readings, SampleStepping::shared_steps,
                     nullptr, compared_samples(d));
    residuals_of(d, readings, r);
    if (!own) return;
    const Eigen::Index n = r.size();
    r.conservativeResize(n + 1);
    r(n) = pinned && block == 0 ? kPinnedScaleWeight * local(3) : 0.0;
  };
  problem.jacobian = [&setup](int block, const Eigen::VectorXd& shared, const Eigen::VectorXd& local,
                              Eigen::VectorXd& r, Eigen::MatrixXd& jacobian) {
    return flight_jacobian(setup, block, shared, local, r, jacobian);
  };
  return problem;
}

void set_flight_thetas(const FitSetup& setup, const Eigen::VectorXd& shared, EffectFit& fit) {
  const FlightOwnParameters* own = setup.own();
  if (own == nullptr || shared.size() < own->shared_count || fit.flights.empty()) return;
  for (FlightState& state : fit.flights)
    state.theta = own->theta_of(shared.head(own->shared_count), state.own);
  fit.theta = fit.flights.front().theta;
}

namespace {

// The errors of the first flight's theta where each flight has parameters of its own: the
// shared ones' (`errors`, own parameters marginalised) and that flight's own, given the
// shared ones (its block of the normal matrix), through theta_of's derivatives; the two
// taken as uncorrelated.
void first_flight_errors(const FitSetup& setup, const LeastSquaresResult& solution, double variance,
                         ParameterErrors& errors) {
  const FlightOwnParameters& own = *setup.own();
  const int s = own.shared_count, k = own.count, m = setup.local_count();
  if (errors.covariance.rows() != s || solution.normal_matrix.rows() < s + m) return;
  Eigen::MatrixXd block = solution.normal_matrix.block(s, s, m, m);
  Eigen::MatrixXd joint = Eigen::MatrixXd::Zero(s + k, s + k);
  joint.topLeftCorner(s, s) = errors.covariance;
  joint.bottomRightCorner(k, k) =
      variance * Eigen::MatrixXd(block.ldlt().solve(Eigen::MatrixXd::Identity(m, m))).bottomRightCorner(k, k);
  Eigen::VectorXd point(s + k);
  point << solution.shared.head(s), solution.local[0].tail(k);
  const Eigen::VectorXd at = own.theta_of(point.head(s), point.tail(k));
  Eigen::MatrixXd derivative(at.size(), s + k);
  for (int i = 0; i < s + k; ++i) {
    Eigen::VectorXd moved = point;
    const double h = forward_difference_step(moved(i));
    moved(i) += h;
    derivative.col(i) = (own.theta_of(moved.head(s), moved.tail(k)) - at) / h;
  }
  errors.covariance = derivative * joint * derivative.transpose();
  errors.standard_error = errors.covariance.diagonal().cwiseMax(0.0).cwiseSqrt();
}

}  // namespace

EffectFit result_of(const FitSetup& setup, const LeastSquaresResult& solution, int shared_count) {
  EffectFit fit;
  fit.effect = setup.effect;
  fit.base = setup.base;
  fit.theta = solution.shared;
  fit.cost = solution.cost;
  fit.residual_count = 0;
  const int own = setup.local_count() - 3;
  for (std::size_t i = 0; i < setup.data->size(); ++i) {
    FlightState state;
    state.ref = setup.refs[i];
    state.omega_ref = Vec3(solution.local[i].head<3>());
    if (own > 0) state.own = solution.local[i].tail(own);
    state.impulse_time_s = setup.impulse_time_s;
    fit.flights.push_back(state);
    fit.residual_count += (*setup.data)[i].residual_count();
  }
  set_flight_thetas(setup, solution.shared, fit);
  const int shared = setup.shared_count(shared_count);
  const int parameters = shared + setup.local_count() * static_cast<int>(setup.data->size());
  const int dof = std::max(1, fit.residual_count - parameters);
  const double variance = std::max(fit.cost / dof, 1e-12);
  ParameterErrors errors = parameter_errors(solution.normal_matrix, shared, setup.local_count(), variance);
  if (own > 0 && shared > 0) first_flight_errors(setup, solution, variance, errors);
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
  options.keep_jacobian =
      setup.data->size() == 1 && !has_searched_time(setup.model()) && setup.own() == nullptr;
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
    const Vec3 rate = nominal_model
                          ? guess
                          : fit_initial_state(model, (*setup.data)[i], setup.refs[i], held, &guess).omega_ref;
    rates[i] = with_own(setup, rate, theta);
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
    rates.emplace_back(with_own(setup,
                                starting_rate((*setup.data)[i], setup.refs[i], nullptr, i, *setup.nominal),
                                Eigen::VectorXd()));
  }
  return rates;
}

}  // namespace aloft::host::diagnose
