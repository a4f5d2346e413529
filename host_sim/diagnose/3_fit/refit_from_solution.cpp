#include "diagnose/3_fit/refit_from_solution.hpp"

#include <algorithm>

#include "diagnose/2_model/reading_derivatives.hpp"
#include "diagnose/3_fit/fit_problem.hpp"
#include "diagnose/3_fit/fit_setup.hpp"
#include "diagnose/3_fit/flight_jacobian.hpp"
#include "diagnose/3_fit/levenberg_marquardt.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

FitSetup solution_setup(const EffectFit& fit, const NominalInertia& nominal,
                        const std::vector<FlightData>& flights, double impulse_time_s) {
  return FitSetup{fit.effect,     &nominal, &flights,         {fit.flights[0].ref},
                  impulse_time_s, fit.base, Eigen::VectorXd()};
}

bool same_values(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && (a.array() == b.array()).all();
}

// `shared` serves a fold's step at (theta, local) over `data`: the same point, impulse
// time and weights, and every sample `data` compares compared there too.
bool serves(const SolutionLinearisation& shared, const FlightData& data, double impulse_time_s,
            const Eigen::VectorXd& theta, const Eigen::VectorXd& local) {
  if (shared.impulse_time_s != impulse_time_s || shared.data.flight != data.flight ||
      !(shared.data.inverse_sigma.array() == data.inverse_sigma.array()).all() ||
      !same_values(shared.theta, theta) || !same_values(shared.omega_ref, local)) {
    return false;
  }
  for (std::size_t k = 0; k < data.mask.size(); ++k) {
    if (data.compared(k) && !shared.data.compared(k)) return false;
  }
  return true;
}

// The fold's residuals and Jacobian from `shared` (linearise_at_solution), as
// flight_jacobian or the fitter's differences make them over the fold itself.
void masked_linearisation(const FitSetup& setup, const SolutionLinearisation& shared, Eigen::VectorXd& r,
                          Eigen::MatrixXd& jacobian) {
  const FlightData& d = (*setup.data)[0];
  r = shared.residuals;
  jacobian = shared.jacobian;
  for (std::size_t k = 0; k < d.flight->size(); ++k) {
    if (d.compared(k)) continue;
    const Eigen::Index row = static_cast<Eigen::Index>(3 * k);
    r.segment<3>(row).setZero();
    jacobian.middleRows<3>(row).setZero();
  }
  const EffectModel model = setup.model();
  const std::vector<char> impulse = impulse_directions(model, shared.theta);
  if (std::find(impulse.begin(), impulse.end(), 1) != impulse.end()) {
    impulse_reading_derivatives(model, *d.flight, setup.refs[0], shared.theta, shared.impulse_rate_derivative,
                                impulse, jacobian);
  }
}

}  // namespace

SolutionLinearisation linearise_at_solution(const EffectFit& fit, const NominalInertia& nominal,
                                            const FlightData& data, double impulse_time_s) {
  const std::vector<FlightData> flights{data};
  const FitSetup setup = solution_setup(fit, nominal, flights, impulse_time_s);
  SolutionLinearisation out;
  out.data = data;
  out.impulse_time_s = impulse_time_s;
  out.theta = fit.theta;
  out.omega_ref = fit.flights[0].omega_ref;
  ArrowProblem problem = problem_of(setup, static_cast<int>(fit.theta.size()));
  problem.jacobian = [&setup, &out](int block, const Eigen::VectorXd& theta, const Eigen::VectorXd& local,
                                    Eigen::VectorXd& r, Eigen::MatrixXd& jacobian) {
    return flight_jacobian(setup, block, theta, local, r, jacobian, &out.impulse_rate_derivative);
  };
  block_jacobian(problem, 0, out.theta, out.omega_ref, nullptr, out.residuals, out.jacobian);
  return out;
}

EffectFit refit_from_solution(const EffectFit& fit, const NominalInertia& nominal, const FlightData& data,
                              double impulse_time_s, const SolutionLinearisation* at_solution) {
  const std::vector<FlightData> flights{data};
  const FitSetup setup = solution_setup(fit, nominal, flights, impulse_time_s);
  ArrowProblem problem = problem_of(setup, static_cast<int>(fit.theta.size()));
  if (at_solution != nullptr) {
    problem.jacobian = [&setup, at_solution, impulse_time_s](int block, const Eigen::VectorXd& theta,
                                                             const Eigen::VectorXd& local, Eigen::VectorXd& r,
                                                             Eigen::MatrixXd& jacobian) {
      if (!serves(*at_solution, (*setup.data)[0], impulse_time_s, theta, local)) {
        return flight_jacobian(setup, block, theta, local, r, jacobian);
      }
      masked_linearisation(setup, *at_solution, r, jacobian);
      return true;
    };
  }
  const std::vector<Eigen::VectorXd> rates{local_of(fit, 0)};
  const LeastSquaresResult step = gauss_newton_step(problem, fit.theta.head(problem.shared_count), rates);
  EffectFit out = fit;
  out.theta = step.shared;
  out.flights[0].omega_ref = Vec3(step.local[0].head<3>());
  out.flights[0].own = step.local[0].tail(step.local[0].size() - 3);
  set_flight_thetas(setup, step.shared, out);
  out.flights[0].impulse_time_s = impulse_time_s;
  out.cost = step.cost;
  out.residual_count = data.residual_count();
  out.other_minima.clear();
  out.linearisation.reset();  // the all-samples fit's, at another point
  return out;
}

std::vector<Eigen::VectorXd> leave_one_flight_out(const EffectFit& fit, const NominalInertia& nominal,
                                                  const std::vector<FlightData>& data, unsigned threads) {
  FitSetup setup{fit.effect, &nominal, &data, {}, 0.0, fit.base, Eigen::VectorXd(), threads};
  for (const FlightState& f : fit.flights) setup.refs.push_back(f.ref);
  const ArrowProblem problem = problem_of(setup, static_cast<int>(fit.theta.size()));
  std::vector<Eigen::VectorXd> rates;
  for (std::size_t i = 0; i < fit.flights.size(); ++i) rates.push_back(local_of(fit, i));
  const Eigen::Index shared = problem.shared_count;
  std::vector<Eigen::VectorXd> out = leave_one_block_out(problem, fit.theta.head(shared), rates);
  // Where each flight has parameters of its own, a whole theta: the shared ones from the
  // others, the rest as fit.theta's (the left-out flight fits its own).
  for (Eigen::VectorXd& theta : out) {
    Eigen::VectorXd whole = fit.theta;
    whole.head(shared) = theta;
    theta = whole;
  }
  return out;
}

}  // namespace aloft::host::diagnose
