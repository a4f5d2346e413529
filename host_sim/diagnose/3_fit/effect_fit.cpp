#include "diagnose/3_fit/effect_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "common/parallel_for.hpp"
#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/3_fit/initial_state_fit.hpp"
#include "diagnose/3_fit/levenberg_marquardt.hpp"
#include "diagnose/3_fit/parameter_errors.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

// The initial rate guess at sample `ref`: the nominal fit's rate there if there is one,
// else the mean of the usable readings within two samples of it.
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

// The weighted residuals, every sample written once (no clearing first). Read through
// plain pointers: writing r through Eigen's made the compiler reload every vector's data
// at each sample (case00: 35.4 -> 26.7 M instructions here, the same arithmetic).
void residuals_of(const FlightData& data, const std::vector<Vec3>& readings, Eigen::VectorXd& r) {
  const Flight& flight = *data.flight;
  const std::size_t n = flight.size();
  r.resize(static_cast<Eigen::Index>(3 * n));
  const char* const mask = data.mask.data();
  const char* const usable = flight.usable.data();
  const Vec3* const predicted = readings.data();
  const Vec3* const read = flight.omega.data();
  const Vec3 weight = data.inverse_sigma;
  double* out = r.data();
  for (std::size_t k = 0; k < n; ++k, out += 3) {
    if (!mask[k] || !usable[k]) {
      out[0] = out[1] = out[2] = 0.0;
    } else {
      for (int i = 0; i < 3; ++i) out[i] = (predicted[k](i) - read[k](i)) * weight(i);
    }
  }
}

// The samples whose readings residuals_of reads: the compared ones.
ReadSamples compared_samples(const FlightData& d) { return {d.mask.data(), d.flight->usable.data()}; }

struct Setup {
  Effect effect;
  const NominalInertia* nominal;
  const std::vector<FlightData>* data;
  std::vector<std::size_t> refs;
  double impulse_time_s = 0.0;
  std::vector<Effect> base;    // compound: effects fitted jointly with `effect`
  Eigen::VectorXd base_theta;  // their fitted values (impulse scan, starting point)
  unsigned threads = 1;        // flights fitted concurrently (a pooled fit)

  EffectModel model() const { return EffectModel{effect, *nominal, impulse_time_s, base}; }
};

// [theta | local] moved by the fitter's forward-difference step along entry i.
struct Shift {
  Eigen::VectorXd theta, local;
  double h = 0.0;
};
Shift shifted(const Eigen::VectorXd& theta, const Eigen::VectorXd& local, Eigen::Index i) {
  Shift out{theta, local, 0.0};
  const Eigen::Index p = theta.size();
  double& value = i < p ? out.theta(i) : out.local(i - p);
  out.h = forward_difference_step(value);
  value += out.h;
  return out;
}

// A Jacobian column of reading derivatives weighted in place as the residuals are: zero
// for the samples the fit leaves out.
void weight_column(const FlightData& d, Eigen::MatrixXd& jacobian, Eigen::Index column) {
  for (std::size_t k = 0; k < d.flight->size(); ++k) {
    const Eigen::Index row = static_cast<Eigen::Index>(3 * k);
    jacobian.block<3, 1>(row, column) =
        d.compared(k) ? Vec3(jacobian.block<3, 1>(row, column).cwiseProduct(d.inverse_sigma)) : Vec3::Zero();
  }
}

// The residuals of one flight and their Jacobian [theta | omega_ref] when some theta
// directions need no simulation: the sensor's (sensor_reading_derivatives) and the
// impulse's (impulse_reading_derivatives, from the rate columns); or when two rate
// columns can be differenced side by side (predict_readings_pair: a model whose
// reference is the release sample, the rotor's, has one walk a prediction; case00
// 437.5 -> 424.6 M instructions). Every other column is differenced exactly as the fitter
// would (same step, same residuals). False when none of these holds: the fitter then
// differences every column itself. `r`: on entry the residuals when known, else empty.
// `rate_derivative` (optional): where the rate columns' change of the rate at the impulse
// goes (impulse_reading_derivatives), when the model has one.
bool flight_jacobian(const Setup& setup, int block, const Eigen::VectorXd& theta,
                     const Eigen::VectorXd& local, Eigen::VectorXd& r, Eigen::MatrixXd& jacobian,
                     Eigen::Matrix3d* rate_derivative = nullptr) {
  const EffectModel model = setup.model();
  const std::vector<char> sensor = sensor_directions(model, theta),
                          impulse = impulse_directions(model, theta);
  const auto none = [](const std::vector<char>& v) { return std::find(v.begin(), v.end(), 1) == v.end(); };
  const FlightData& d = (*setup.data)[static_cast<std::size_t>(block)];
  const Flight& flight = *d.flight;
  const std::size_t ref = setup.refs[static_cast<std::size_t>(block)];
  const Eigen::Index p = theta.size(), m = local.size();
  const bool paired_rates = (ref == 0 || ref + 1 == flight.size()) && none(impulse) && m == 3;
  if (none(sensor) && none(impulse) && !paired_rates) return false;
  std::vector<Vec3> readings, readings_b;
  Vec3 at_impulse = Vec3::Zero(), moved_at_impulse = Vec3::Zero();
  const ReadSamples read = compared_samples(d);
  if (!none(sensor) || !none(impulse) || r.size() == 0) {
    predict_readings(model, flight, ref, Vec3(local), theta, readings, SampleStepping::shared_steps,
                     &at_impulse, read);
    residuals_of(d, readings, r);
  }
  jacobian.resize(r.size(), p + m);
  if (!none(sensor)) sensor_reading_derivatives(model, flight, theta, readings, sensor, jacobian);
  Eigen::Matrix3d impulse_rate_derivative = Eigen::Matrix3d::Identity();
  Eigen::VectorXd moved;
  Eigen::Index differenced = p + m;
  if (paired_rates) {  // the last two rate columns side by side
    Eigen::VectorXd local_a = local, local_b = local;
    const double h_a = forward_difference_step(local_a(m - 1)), h_b = forward_difference_step(local_b(m - 2));
    local_a(m - 1) += h_a;
    local_b(m - 2) += h_b;
    predict_readings_pair(model, flight, ref, Vec3(local_a), Vec3(local_b), theta, readings, readings_b,
                          read);
    residuals_of(d, readings, moved);
    jacobian.col(p + m - 1) = (moved - r) / h_a;
    residuals_of(d, readings_b, moved);
    jacobian.col(p + m - 2) = (moved - r) / h_b;
    differenced = p + m - 2;
  }
  // Differenced columns, the rates' first: the impulse's columns are made from them.
  std::vector<Eigen::Index> columns;
  for (Eigen::Index i = differenced; i-- > 0;) {
    if (i >= p || !(sensor[static_cast<std::size_t>(i)] || impulse[static_cast<std::size_t>(i)])) {
      columns.push_back(i);
    }
  }
  std::size_t next = 0;
  // With one walk a prediction (and no impulse), two at a time side by side, each lane
  // with its own theta (predict_readings_two): a rotor's (case00 377.0 -> 367.9 M).
  for (; paired_rates && next + 1 < columns.size(); next += 2) {
    const Shift a = shifted(theta, local, columns[next]), b = shifted(theta, local, columns[next + 1]);
    predict_readings_two(model, flight, ref, Vec3(a.local), a.theta, Vec3(b.local), b.theta, readings,
                         readings_b, read);
    residuals_of(d, readings, moved);
    jacobian.col(columns[next]) = (moved - r) / a.h;
    residuals_of(d, readings_b, moved);
    jacobian.col(columns[next + 1]) = (moved - r) / b.h;
  }
  for (; next < columns.size(); ++next) {
    const Eigen::Index i = columns[next];
    const Shift a = shifted(theta, local, i);
    predict_readings(model, flight, ref, Vec3(a.local), a.theta, readings, SampleStepping::shared_steps,
                     &moved_at_impulse, read);
    residuals_of(d, readings, moved);
    jacobian.col(i) = (moved - r) / a.h;
    if (i >= p) impulse_rate_derivative.col(i - p) = (moved_at_impulse - at_impulse) / a.h;
  }
  if (!none(impulse)) {
    impulse_reading_derivatives(model, flight, ref, theta, impulse_rate_derivative, impulse, jacobian);
    if (rate_derivative != nullptr) *rate_derivative = impulse_rate_derivative;
  }
  for (Eigen::Index i = 0; i < p; ++i) {
    if (sensor[static_cast<std::size_t>(i)]) weight_column(d, jacobian, i);
  }
  return true;
}

ArrowProblem problem_of(const Setup& setup, int shared_count) {
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

EffectFit result_of(const Setup& setup, const LeastSquaresResult& solution, int shared_count) {
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

// A fit's options: a single flight's fit without an impulse keeps its residuals and
// Jacobian at the solution (EffectFit::linearisation); an impulse's columns need the
// rate at the jump as well, which the fitter does not keep.
LeastSquaresOptions solution_options(const Setup& setup) {
  LeastSquaresOptions options;
  options.keep_jacobian = setup.data->size() == 1 && !has_searched_time(setup.model());
  return options;
}

// Each flight's starting rate: the guess of starting_rate, refined with `theta` held by
// the separatrix-safe initial-state fit (initial_state_fit.hpp). The rotor of internal
// damping has no neutral theta, so its flights start from the rigid body's rates.
std::vector<Eigen::VectorXd> starting_rates(const Setup& setup, const EffectFit* nominal_fit,
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

// Each flight's rate at its reference sample as the gyro reads it there (the mean of the
// usable readings within two samples): a start of a grid away from the nominal model has no
// fitted rate, and the nominal fit's rate suits the nominal moments only.
std::vector<Eigen::VectorXd> rates_read_at_reference(const Setup& setup) {
  std::vector<Eigen::VectorXd> rates;
  for (std::size_t i = 0; i < setup.data->size(); ++i) {
    rates.emplace_back(starting_rate((*setup.data)[i], setup.refs[i], nullptr, i, *setup.nominal));
  }
  return rates;
}

// The impulse time is not a smooth parameter (the jump moves from one sample to the
// next), so it is searched. First a linearised scan of every time between samples at
// once: about the nominal motion (dw = 0) the readings' sensitivity to a jump just before
// sample j is A_k A_j^-1 for the samples on the far side of the jump from the reference
// (A_k = d reading_k / d omega_ref, the flow map), so one Gauss-Newton step for (omega_ref,
// dw) at every j needs only running sums of A_k^T W A_k and A_k^T W r_k. Then full fits at
// the best few times of the scan and their neighbours; the best of those wins.
struct ScanPeak {
  std::size_t at = 0;
  double gain = 0.0;
};
std::vector<ScanPeak> scan_impulse_times(const Setup& setup, const std::vector<Eigen::VectorXd>& rates) {
  const FlightData& data = (*setup.data)[0];
  const Flight& flight = *data.flight;
  const std::size_t n = flight.size();
  const std::size_t ref = setup.refs[0];
  // About the base model with its fitted parameters (the nominal one for a single effect).
  const EffectModel nominal_model{Effect::none, *setup.nominal, 0.0, setup.base};
  const Eigen::VectorXd no_theta = setup.base_theta;
  std::vector<Vec3> base, moved;
  predict_readings(nominal_model, flight, ref, Vec3(rates[0]), no_theta, base);
  std::vector<Eigen::Matrix3d> a(n);
  for (int i = 0; i < 3; ++i) {
    Vec3 w = rates[0];
    const double h = 1e-6 * std::max(1.0, w.norm());
    w(i) += h;
    predict_readings(nominal_model, flight, ref, w, no_theta, moved);
    for (std::size_t k = 0; k < n; ++k) a[k].col(i) = (moved[k] - base[k]) / h;
  }
  // Weighted per-sample blocks of the normal equations.
  std::vector<Eigen::Matrix3d> m(n, Eigen::Matrix3d::Zero());
  std::vector<Vec3> v(n, Vec3::Zero());
  Eigen::Matrix3d m_all = Eigen::Matrix3d::Zero();
  Vec3 v_all = Vec3::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    if (!data.compared(k)) continue;
    const Eigen::Matrix3d wa = data.inverse_sigma.asDiagonal() * a[k];
    const Vec3 wr = (base[k] - flight.omega[k]).cwiseProduct(data.inverse_sigma);
    m[k] = wa.transpose() * wa;
    v[k] = wa.transpose() * wr;
    m_all += m[k];
    v_all += v[k];
  }
  // suffix[j] = sum over k >= j.
  std::vector<Eigen::Matrix3d> m_after(n + 1, Eigen::Matrix3d::Zero());
  std::vector<Vec3> v_after(n + 1, Vec3::Zero());
  for (std::size_t k = n; k-- > 0;) {
    m_after[k] = m_after[k + 1] + m[k];
    v_after[k] = v_after[k + 1] + v[k];
  }
  std::vector<std::pair<double, std::size_t>> gains;
  for (std::size_t j = 2; j + 1 < n; ++j) {                        // jump between samples j-1 and j
    if (flight.time_s[j - 1] < flight.settling_until_s) continue;  // the gyro's filter settling
    const bool after_reference = j > ref;
    const std::size_t anchor = after_reference ? j : j - 1;
    const Eigen::Matrix3d side_m = after_reference ? m_after[j] : Eigen::Matrix3d(m_all - m_after[j]);
    const Vec3 side_v = after_reference ? v_after[j] : Vec3(v_all - v_after[j]);
    const Eigen::Matrix3d inv = a[anchor].inverse();
    Eigen::Matrix<double, 6, 6> hess;
    hess.topLeftCorner<3, 3>() = m_all;
    hess.topRightCorner<3, 3>() = side_m * inv;
    hess.bottomLeftCorner<3, 3>() = hess.topRightCorner<3, 3>().transpose();
    hess.bottomRightCorner<3, 3>() = inv.transpose() * side_m * inv;
    Eigen::Matrix<double, 6, 1> grad;
    grad.head<3>() = v_all;
    grad.tail<3>() = inv.transpose() * side_v;
    const Eigen::Matrix<double, 6, 1> step = hess.ldlt().solve(grad);
    const double gain = grad.dot(step);
    if (std::isfinite(gain)) gains.emplace_back(gain, j);
  }
  std::sort(gains.begin(), gains.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  // The best two times at least 10 samples apart. A real knock lasts a few milliseconds
  // and the linear scan tends to flag its start, so the full fits look around each.
  std::vector<ScanPeak> peaks;
  for (const auto& g : gains) {
    bool far = true;
    for (const ScanPeak& p : peaks) far = far && (g.second + 10 < p.at || p.at + 10 < g.second);
    if (far) peaks.push_back({g.second, g.first});
    if (peaks.size() == 2) break;
  }
  return peaks;
}

// From the best time so far, each way: a step that lowers the cost is taken and the next
// step doubles; one that does not is halved, down to a single sample. When the nominal
// motion is far off the true one, the scan peaks where the gap is largest, not where it
// begins, and the cost then falls steadily towards the true time over a hundred samples
// or more: the windows round the peaks stop short of it. Near the right time this costs
// four trials, the neighbours at 1 and 2 samples that were tried before anyway.
template <class TryTime>
void walk_downhill(std::size_t& best, TryTime try_time) {
  for (long direction : {-1L, 1L}) {
    for (long step = 2; step >= 1;) {
      const std::size_t from = best;
      try_time(static_cast<long>(best) + direction * step);
      step = best != from ? 2 * step : step / 2;
    }
  }
}

// One quick fit of a search: where it was tried and what it reached.
struct Trial {
  std::size_t at = 0;  // impulse: the sample after the jump; a grid: the start's index
  double cost = 0.0;
  Eigen::VectorXd theta;
  std::vector<Eigen::VectorXd> rates;
};

// Each trial's cost as it stands (cost_at); of one flight, two trials at a time side by
// side (predict_readings_two: the damping grid's rotors, one walk a prediction, in the
// paired steps; case00 366.2 -> 362.5 M), the cost summed as the fitter sums it.
void grid_costs(const Setup& setup, const ArrowProblem& problem, std::vector<Trial>& trials) {
  std::size_t next = 0;
  for (; setup.data->size() == 1 && next + 1 < trials.size(); next += 2) {
    const FlightData& d = (*setup.data)[0];
    Trial &a = trials[next], &b = trials[next + 1];
    std::vector<Vec3> readings_a, readings_b;
    predict_readings_two(setup.model(), *d.flight, setup.refs[0], Vec3(a.rates[0]), a.theta, Vec3(b.rates[0]),
                         b.theta, readings_a, readings_b, compared_samples(d));
    Eigen::VectorXd r;
    for (Trial* t : {&a, &b}) {
      residuals_of(d, t == &a ? readings_a : readings_b, r);
      t->cost = 0.0;
      t->cost += r.squaredNorm();
      if (!std::isfinite(t->cost)) t->cost = std::numeric_limits<double>::infinity();
    }
  }
  for (; next < trials.size(); ++next)
    trials[next].cost = cost_at(problem, trials[next].theta, trials[next].rates);
}

bool within_window(double cost, double best_cost) {
  return cost - best_cost <= std::max(kOtherMinimumWindow, kOtherMinimumWindowShare * best_cost);
}

// A refined minimum of a search, and the impulse time it holds (impulse only).
struct Refined {
  LeastSquaresResult result;
  double impulse_time_s = 0.0;
};

// Of the chosen refined minimum and another, the lower is kept and the other recorded.
EffectFit keep_lower(Setup& setup, int p, Refined chosen, std::optional<Refined> other) {
  if (other && other->result.cost < chosen.result.cost) std::swap(chosen, *other);
  setup.impulse_time_s = chosen.impulse_time_s;
  EffectFit fit = result_of(setup, chosen.result, p);
  if (other) fit.other_minima.push_back({other->result.shared, other->impulse_time_s, other->result.cost});
  return fit;
}

// The best quick fit more than 10 samples (the peaks' separation) from the chosen time,
// refined at its time, when it came within the window.
std::optional<Refined> other_impulse_time(Setup& setup, int p, const std::vector<Trial>& trials,
                                          std::size_t best, double best_cost) {
  const Trial* other = nullptr;
  for (const Trial& t : trials) {
    const bool far = t.at + 10 < best || best + 10 < t.at;
    if (far && (other == nullptr || t.cost < other->cost)) other = &t;
  }
  if (other == nullptr || !within_window(other->cost, best_cost)) return std::nullopt;
  const Flight& flight = *(*setup.data)[0].flight;
  setup.impulse_time_s = 0.5 * (flight.time_s[other->at - 1] + flight.time_s[other->at]);
  return Refined{minimise(problem_of(setup, p), other->theta, other->rates), setup.impulse_time_s};
}

// Two minima of a start grid differ by more than the grid's `distinct` in a parameter.
bool distinct_minima(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const StartGrid& grid) {
  return a.size() == b.size() && (a - b).cwiseAbs().maxCoeff() > grid.distinct;
}

// The best start of the grid that had reached another minimum than the chosen one,
// refined, when it came within the window and stayed distinct.
std::optional<Refined> other_grid_minimum(const ArrowProblem& problem, const std::vector<Trial>& trials,
                                          const Trial& best, const Eigen::VectorXd& chosen,
                                          const StartGrid& grid, const LeastSquaresOptions& options) {
  const Trial* other = nullptr;
  for (const Trial& t : trials) {
    if (&t == &best || !distinct_minima(t.theta, best.theta, grid)) continue;
    if (other == nullptr || t.cost < other->cost) other = &t;
  }
  if (other == nullptr || !within_window(other->cost, best.cost)) return std::nullopt;
  LeastSquaresResult r = minimise(problem, other->theta, other->rates, options);
  if (!distinct_minima(r.shared, chosen, grid)) return std::nullopt;
  return Refined{std::move(r), 0.0};
}

// The window of quick fits round each scanned peak: every third gap within 6 samples
// (4 fits a peak; the downhill walk goes on from the best). Against 12 samples (8 a
// peak): case00 714 -> 586 M instructions; over the 65 trials of make_reports.sh no
// headline, effect or confident flag moved, and of the verdicts' lists of equivalent or
// indistinguishable candidates one step's (docs/diagnose.md, speed). Sparser or narrower
// windows saved more but moved more: every 4th or 6th gap within 12 (642, 582 M) also
// put aero_torque among a racquet flight's indistinguishable candidates; the gaps at 3
// only (517 M) or the peaks alone (448 M) took practice3/T04's first flight from
// gyro_scale + impulse to clock_drift.
constexpr long kTimeWindowRadius = 6;
constexpr long kTimeWindowStride = 3;
// Round the scan's second peak (the best time at least 10 samples from the first): the
// window only where the peak's gain (the linearised cost fall) is at least 0.95 of the
// first's, and then only the gaps at 3. It is still tried itself, from the nominal
// solution, so a second minimum there is still seen. On the 65 trials the gain ratio's
// median is 0.90 and about 570 of 920 searches leave the window out; case00 586 -> 521 M
// (ratios 0.94, 0.76 and 0.89 on its three searches), and the 65 trials' headlines,
// effects, confident flags and lists are then all main's (practice2/A02's list back too).
// The ratio alone, with the second window as wide as the first, 521 M, moved A02's list.
constexpr double kSecondPeakGainShare = 0.95;
constexpr long kSecondPeakWindowRadius = 3;

// An effect that acts at one instant (descriptor `searched_parameters`: the impulse): its
// time is searched over the flight, the rest fitted at each time tried.
EffectFit fit_with_time_search(Setup& setup, const EffectFit* nominal_fit) {
  const Flight& flight = *(*setup.data)[0].flight;
  const int p = static_cast<int>(setup.base_theta.size()) + effect_parameter_count(setup.effect);
  Eigen::VectorXd zero = Eigen::VectorXd::Zero(p);
  zero.head(setup.base_theta.size()) = setup.base_theta;
  const std::vector<Eigen::VectorXd> rates = starting_rates(setup, nominal_fit, zero);
  LeastSquaresOptions quick;
  quick.max_iterations = 10;
  quick.normal_at_solution = false;  // only the costs are compared
  const std::size_t n = flight.size();
  std::size_t best = 0;
  double best_cost = std::numeric_limits<double>::infinity();
  // Each trial starts from the best solution so far: neighbouring times have nearly the
  // same jump and rates, so a few iterations settle it.
  Eigen::VectorXd best_theta = zero;
  std::vector<Eigen::VectorXd> best_rates = rates;
  std::vector<Trial> trials;
  auto try_time = [&](std::size_t j, bool from_nominal) {
    if (j < 2 || j + 1 >= n || flight.time_s[j - 1] < flight.settling_until_s) return;
    setup.impulse_time_s = 0.5 * (flight.time_s[j - 1] + flight.time_s[j]);
    const LeastSquaresResult r = from_nominal ? minimise(problem_of(setup, p), zero, rates, quick)
                                              : minimise(problem_of(setup, p), best_theta, best_rates, quick);
    trials.push_back({j, r.cost, r.shared, r.local});
    if (r.cost < best_cost) {
      best_cost = r.cost;
      best = j;
      best_theta = r.shared;
      best_rates = r.local;
    }
  };
  // Around each scanned peak: every third gap within 6 samples (the second peak's within
  // 3, and only where its gain comes near the first's); then downhill from the best.
  const std::vector<ScanPeak> peaks = scan_impulse_times(setup, rates);
  for (std::size_t i = 0; i < peaks.size(); ++i) {
    const std::size_t peak = peaks[i].at;
    try_time(peak, true);
    if (i > 0 && peaks[i].gain < kSecondPeakGainShare * peaks[0].gain) continue;
    const long radius = i > 0 ? kSecondPeakWindowRadius : kTimeWindowRadius;
    for (long off = -radius; off <= radius; off += kTimeWindowStride) {
      if (off != 0) try_time(static_cast<std::size_t>(std::max(0L, static_cast<long>(peak) + off)), false);
    }
  }
  walk_downhill(best, [&](long j) { try_time(static_cast<std::size_t>(std::max(0L, j)), false); });
  if (best == 0) best = flight.size() / 2;
  std::optional<Refined> other = other_impulse_time(setup, p, trials, best, best_cost);
  setup.impulse_time_s = 0.5 * (flight.time_s[best - 1] + flight.time_s[best]);
  Refined chosen{minimise(problem_of(setup, p), best_theta, best_rates), setup.impulse_time_s};
  return keep_lower(setup, p, std::move(chosen), std::move(other));
}

}  // namespace

EffectModel model_of(const EffectFit& fit, const NominalInertia& nominal, std::size_t index) {
  EffectModel model{fit.effect, nominal, 0.0, fit.base};
  if (index < fit.flights.size()) model.impulse_time_s = fit.flights[index].impulse_time_s;
  return model;
}

void predict(const EffectFit& fit, const NominalInertia& nominal, std::size_t index, const Flight& flight,
             std::vector<Eigen::Vector3d>& readings) {
  const FlightState& state = fit.flights[index];
  predict_readings(model_of(fit, nominal, index), flight, state.ref, state.omega_ref, fit.theta, readings);
}

double weighted_squares(const FlightData& data, const std::vector<Eigen::Vector3d>& readings,
                        int* residual_count) {
  double sum = 0.0;
  int count = 0;
  const Flight& flight = *data.flight;
  for (std::size_t k = 0; k < flight.size(); ++k) {
    if (!data.compared(k)) continue;
    sum += (readings[k] - flight.omega[k]).cwiseProduct(data.inverse_sigma).squaredNorm();
    count += 3;
  }
  if (residual_count != nullptr) *residual_count = count;
  return sum;
}

namespace {

// Where the effect has a start read off the readings (descriptor `start_from_readings`: a
// rotor) and that start, with the rates the gyro reads, already costs less than where the
// fit ended (one simulation), the fit stopped in another minimum: it is fitted again from
// there and the lower end kept. A fit that reached its minimum is kept as it is. `base`:
// the base effects' fitted parameters, which head theta and the start (compound models).
LeastSquaresResult lower_from_readings(const Setup& setup, const ArrowProblem& problem,
                                       LeastSquaresResult fitted, const Eigen::VectorXd& base) {
  const auto read_off = describe(setup.effect).start_from_readings;
  if (read_off == nullptr) return fitted;
  std::vector<const Flight*> flights;
  for (const FlightData& d : *setup.data) flights.push_back(d.flight);
  Eigen::VectorXd start(fitted.shared.size());
  start << base, read_off(flights, *setup.nominal);
  const std::vector<Eigen::VectorXd> rates = rates_read_at_reference(setup);
  if (!(cost_at(problem, start, rates) < fitted.cost)) return fitted;
  LeastSquaresResult again = minimise(problem, start, rates, solution_options(setup));
  return again.cost < fitted.cost ? again : fitted;
}

}  // namespace

EffectFit fit_effect(Effect effect, const NominalInertia& nominal, const std::vector<FlightData>& data,
                     const EffectFit* nominal_fit, const Eigen::VectorXd* theta_start, unsigned threads) {
  Setup setup{effect, &nominal, &data, {}, 0.0, {}, Eigen::VectorXd(), threads};
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
  if (!seeded && grid != nullptr) {
    // A look over the whole grid first: each start's cost as it stands, with the
    // starting rates (one simulation a start, no Jacobian); then the best start is
    // refined, and the best other within the window (other_grid_minimum). Giving every
    // start four iterations instead cost 300 M of case00's 1,494 M instructions; the
    // headlines of the 65 report trials and the diagnose tests' figures are the same.
    // Where zero is the nominal model, the nominal fit's rates suit zero only; a start
    // away from it is costed with the rates the gyro reads (practice3/T06: from the nominal
    // rates the true moments, a start of the grid, cost more than zero on every flight).
    std::vector<Trial> trials;
    const bool neutral_at_zero = describe(effect).neutral_at_zero;
    const std::vector<Eigen::VectorXd> read_rates =
        neutral_at_zero ? rates_read_at_reference(setup) : std::vector<Eigen::VectorXd>{};
    for (const Eigen::VectorXd& start : grid->starts()) {
      const bool away = neutral_at_zero && !start.isZero();
      trials.push_back({trials.size(), 0.0, start, away ? read_rates : rates});
    }
    grid_costs(setup, problem, trials);
    // The first of equal costs: the grid's order, not the last bits, breaks a tie.
    const Trial& best = *std::min_element(trials.begin(), trials.end(),
                                          [](const Trial& a, const Trial& b) { return a.cost < b.cost; });
    Refined chosen{minimise(problem, best.theta, best.rates, solution_options(setup)), 0.0};
    std::optional<Refined> other =
        other_grid_minimum(problem, trials, best, chosen.result.shared, *grid, solution_options(setup));
    return keep_lower(setup, p, std::move(chosen), std::move(other));
  }
  LeastSquaresResult fitted = minimise(problem, theta, rates, solution_options(setup));
  if (!seeded) fitted = lower_from_readings(setup, problem, std::move(fitted), Eigen::VectorXd());
  return result_of(setup, fitted, p);
}

EffectFit fit_added_effect(const EffectFit& base, Effect added, const NominalInertia& nominal,
                           const std::vector<FlightData>& data, const Eigen::VectorXd* theta_start,
                           unsigned threads, bool readings_start_when_seeded) {
  if (base.effect == Effect::none && base.base.empty()) {
    return fit_effect(added, nominal, data, &base, theta_start, threads);
  }
  Setup setup{added, &nominal, &data, {}, 0.0, base.base, base.theta, threads};
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

namespace {

Setup solution_setup(const EffectFit& fit, const NominalInertia& nominal,
                     const std::vector<FlightData>& flights, double impulse_time_s) {
  return Setup{fit.effect,     &nominal, &flights,         {fit.flights[0].ref},
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
void masked_linearisation(const Setup& setup, const SolutionLinearisation& shared, Eigen::VectorXd& r,
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
  const Setup setup = solution_setup(fit, nominal, flights, impulse_time_s);
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
  const Setup setup = solution_setup(fit, nominal, flights, impulse_time_s);
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
  const std::vector<Eigen::VectorXd> rates{Eigen::VectorXd(fit.flights[0].omega_ref)};
  const LeastSquaresResult step = gauss_newton_step(problem, fit.theta, rates);
  EffectFit out = fit;
  out.theta = step.shared;
  out.flights[0].omega_ref = Vec3(step.local[0]);
  out.flights[0].impulse_time_s = impulse_time_s;
  out.cost = step.cost;
  out.residual_count = data.residual_count();
  out.other_minima.clear();
  out.linearisation.reset();  // the all-samples fit's, at another point
  return out;
}

std::vector<Eigen::VectorXd> leave_one_flight_out(const EffectFit& fit, const NominalInertia& nominal,
                                                  const std::vector<FlightData>& data, unsigned threads) {
  Setup setup{fit.effect, &nominal, &data, {}, 0.0, fit.base, Eigen::VectorXd(), threads};
  for (const FlightState& f : fit.flights) setup.refs.push_back(f.ref);
  const ArrowProblem problem = problem_of(setup, static_cast<int>(fit.theta.size()));
  std::vector<Eigen::VectorXd> rates;
  for (const FlightState& f : fit.flights) rates.emplace_back(Eigen::VectorXd(f.omega_ref));
  return leave_one_block_out(problem, fit.theta, rates);
}

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
EffectFit rates_fitted_from(const Setup& setup, const EffectFit& fixed,
                            const std::vector<Eigen::VectorXd>& starts) {
  const ArrowProblem problem = problem_of(setup, 0);
  LeastSquaresOptions options;
  options.normal_at_solution = false;  // no effect parameter to give an error for
  const LeastSquaresResult solution =
      minimise(rates_only(problem, fixed.theta), Eigen::VectorXd(), starts, options);
  EffectFit fit = result_of(setup, solution, 0);
  fit.theta = fixed.theta;
  fit.theta_standard_error = fixed.theta_standard_error;
  return fit;
}

Setup rates_setup(const EffectFit& fixed, const NominalInertia& nominal,
                  const std::vector<FlightData>& data) {
  Setup setup{fixed.effect, &nominal, &data, {}, 0.0, fixed.base, Eigen::VectorXd()};
  for (const FlightData& d : data) {
    setup.refs.push_back(compound_reference_index(setup.model(), *d.flight));
  }
  return setup;
}

}  // namespace

EffectFit fit_initial_rates(const EffectFit& fixed, const NominalInertia& nominal,
                            const std::vector<FlightData>& data, const EffectFit* nominal_fit) {
  const Setup setup = rates_setup(fixed, nominal, data);
  return rates_fitted_from(setup, fixed, starting_rates(setup, nominal_fit, fixed.theta));
}

EffectFit fit_initial_rates_near(const EffectFit& fixed, const NominalInertia& nominal,
                                 const FlightData& data, const EffectFit& near, std::size_t index,
                                 const EffectFit* nominal_fit) {
  const std::vector<FlightData> flights{data};
  const Setup setup = rates_setup(fixed, nominal, flights);
  if (index >= near.flights.size() || near.flights[index].ref != setup.refs[0] ||
      near.theta.size() != fixed.theta.size()) {
    return fit_initial_rates(fixed, nominal, flights, nominal_fit);
  }
  const std::vector<Eigen::VectorXd> start{Eigen::VectorXd(near.flights[index].omega_ref)};
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
