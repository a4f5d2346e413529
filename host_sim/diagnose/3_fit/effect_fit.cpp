#include "diagnose/3_fit/effect_fit.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/3_fit/fit_problem.hpp"
#include "diagnose/3_fit/fit_setup.hpp"
#include "diagnose/3_fit/levenberg_marquardt.hpp"
#include "diagnose/3_fit/start_search.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

// Where the effect has a start read off the readings (descriptor `start_from_readings`: a
// rotor) and that start, with the rates the gyro reads, already costs less than where the
// fit ended (one simulation), the fit stopped in another minimum: it is fitted again from
// there and the lower end kept. A fit that reached its minimum is kept as it is. `base`:
// the base effects' fitted parameters, which head theta and the start (compound models).
LeastSquaresResult lower_from_readings(const FitSetup& setup, const ArrowProblem& problem,
                                       LeastSquaresResult fitted, const Eigen::VectorXd& base) {
  const auto read_off = describe(setup.effect).start_from_readings;
  if (read_off == nullptr) return fitted;
  std::vector<const Flight*> flights;
  for (const FlightData& d : *setup.data) flights.push_back(d.flight);
  Eigen::VectorXd whole(base.size() + effect_parameter_count(setup.effect));
  whole << base, read_off(flights, *setup.nominal);
  Eigen::VectorXd start = whole.head(problem.shared_count);
  std::vector<Eigen::VectorXd> rates = rates_read_at_reference(setup);
  // Each flight's own parameters (FitSetup::own) read off its own readings, the shared
  // part scaled to the first flight's (whose scale the fit pins at 0).
  if (const FlightOwnParameters* own = setup.own()) {
    for (std::size_t i = 0; i < flights.size(); ++i) {
      const Eigen::VectorXd its = flights.size() > 1 ? read_off({flights[i]}, *setup.nominal) : whole;
      rates[i].tail(own->count) = own->own_of(its, start);
    }
    const double first = rates[0](3);
    start *= std::exp(first);
    for (Eigen::VectorXd& local : rates) local(3) -= first;
  }
  if (!(cost_at(problem, start, rates) < fitted.cost)) return fitted;
  LeastSquaresResult again = minimise(problem, start, rates, solution_options(setup));
  return again.cost < fitted.cost ? again : fitted;
}

}  // namespace

EffectFit fit_effect(Effect effect, const NominalInertia& nominal, const std::vector<FlightData>& data,
                     const EffectFit* nominal_fit, const Eigen::VectorXd* theta_start, unsigned threads) {
  FitSetup setup{effect, &nominal, &data, {}, 0.0, {}, Eigen::VectorXd(), threads};
  for (const FlightData& d : data) setup.refs.push_back(reference_index(effect, *d.flight));
  if (describe(effect).searched_parameters > 0) {
    if (data.size() != 1) throw std::invalid_argument("an impulse is fitted to one flight only");
    return fit_with_time_search(setup, nominal_fit);
  }
  const int p = effect_parameter_count(effect);
  const ArrowProblem problem = problem_of(setup, p);
  const bool seeded = theta_start != nullptr && theta_start->size() == p;
  Eigen::VectorXd theta = seeded ? *theta_start : Eigen::VectorXd::Zero(p);
  const std::vector<Eigen::VectorXd> rates = starting_rates(setup, nominal_fit, theta);
  const StartGrid* grid = describe(effect).start_grid;
  if (!seeded && grid != nullptr) return fit_from_start_grid(setup, problem, *grid, rates, p);
  LeastSquaresResult fitted =
      minimise(problem, theta.head(problem.shared_count), rates, solution_options(setup));
  if (!seeded) fitted = lower_from_readings(setup, problem, std::move(fitted), Eigen::VectorXd());
  return result_of(setup, fitted, p);
}

namespace {

// fit_added_effect from base's fit; where `readings_start_when_seeded`, a seeded fit is
// also tried from the added effect's start read off the readings (SecondStart).
EffectFit fit_added_from(const EffectFit& base, Effect added, const NominalInertia& nominal,
                         const std::vector<FlightData>& data, const Eigen::VectorXd* theta_start,
                         unsigned threads, bool readings_start_when_seeded) {
  if (base.effect == Effect::none && base.base.empty()) {
    return fit_effect(added, nominal, data, &base, theta_start, threads);
  }
  FitSetup setup{added, &nominal, &data, {}, 0.0, base.base, base.theta, threads};
  if (base.effect != Effect::none) setup.base.push_back(base.effect);
  const EffectModel model = setup.model();
  for (std::size_t i = 0; i < data.size(); ++i) {
    setup.refs.push_back(compound_reference_index(model, *data[i].flight));
    if (i < base.flights.size() && has_searched_time(model) && describe(added).searched_parameters == 0) {
      setup.impulse_time_s = base.flights[i].impulse_time_s;
    }
  }
  if (describe(added).searched_parameters > 0) {
    if (data.size() != 1) throw std::invalid_argument("an impulse is fitted to one flight only");
    return fit_with_time_search(setup, &base);
  }
  const int p = model_parameter_count(model);
  const ArrowProblem problem = problem_of(setup, p);
  std::vector<Eigen::VectorXd> rates;
  for (std::size_t i = 0; i < data.size(); ++i) {
    const bool same_ref = i < base.flights.size() && base.flights[i].ref == setup.refs[i];
    rates.emplace_back(same_ref ? Vec3(base.flights[i].omega_ref)
                                : starting_rate(data[i], setup.refs[i], &base, i, nominal));
  }
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(p);
  theta.head(base.theta.size()) = base.theta;
  const bool seeded = theta_start != nullptr && theta_start->size() == p;
  if (seeded) {
    theta = *theta_start;
  } else if (const StartGrid* grid = describe(added).start_grid) {
    const Eigen::VectorXd joining = grid->joining();
    theta.tail(joining.size()) = joining;
  }
  LeastSquaresResult fitted = minimise(problem, theta, rates, solution_options(setup));
  if (!seeded) {
    fitted = lower_from_readings(setup, problem, std::move(fitted), base.theta);
  } else if (readings_start_when_seeded) {
    fitted = lower_from_readings(setup, problem, std::move(fitted), theta_start->head(base.theta.size()));
  }
  return result_of(setup, fitted, p);
}

}  // namespace

EffectFit fit_added_effect(const EffectFit& base, Effect added, const NominalInertia& nominal,
                           const std::vector<FlightData>& data, const Eigen::VectorXd* theta_start,
                           unsigned threads, SecondStart second) {
  const bool readings_when_seeded = second == SecondStart::readings_when_seeded;
  EffectFit fit = fit_added_from(base, added, nominal, data, theta_start, threads, readings_when_seeded);
  const bool from_nominal = second == SecondStart::base_at_nominal && theta_start == nullptr &&
                            base.theta.size() > 0 && describe(added).start_from_readings != nullptr;
  if (!from_nominal) return fit;
  EffectFit at_nominal = base;
  at_nominal.theta.setZero();
  EffectFit other = fit_added_from(at_nominal, added, nominal, data, nullptr, threads, false);
  return other.cost < fit.cost ? other : fit;
}

}  // namespace aloft::host::diagnose
