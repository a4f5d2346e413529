#include "diagnose/3_fit/start_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "diagnose/3_fit/fit_problem.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

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
std::vector<ScanPeak> scan_impulse_times(const FitSetup& setup, const std::vector<Eigen::VectorXd>& rates) {
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
void grid_costs(const FitSetup& setup, const ArrowProblem& problem, std::vector<Trial>& trials) {
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
EffectFit keep_lower(FitSetup& setup, int p, Refined chosen, std::optional<Refined> other) {
  if (other && other->result.cost < chosen.result.cost) std::swap(chosen, *other);
  setup.impulse_time_s = chosen.impulse_time_s;
  EffectFit fit = result_of(setup, chosen.result, p);
  if (other) fit.other_minima.push_back({other->result.shared, other->impulse_time_s, other->result.cost});
  return fit;
}

// The best quick fit more than 10 samples (the peaks' separation) from the chosen time,
// refined at its time, when it came within the window.
std::optional<Refined> other_impulse_time(FitSetup& setup, int p, const std::vector<Trial>& trials,
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

}  // namespace

EffectFit fit_with_time_search(FitSetup& setup, const EffectFit* nominal_fit) {
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

EffectFit fit_from_start_grid(FitSetup& setup, const ArrowProblem& problem, const StartGrid& grid,
                              const std::vector<Eigen::VectorXd>& rates, int p) {
  // A look over the whole grid first: each start's cost as it stands, with the
  // starting rates (one simulation a start, no Jacobian); then the best start is
  // refined, and the best other within the window (other_grid_minimum). Giving every
  // start four iterations instead cost 300 M of case00's 1,494 M instructions; the
  // headlines of the 65 report trials and the diagnose tests' figures are the same.
  // Where zero is the nominal model, the nominal fit's rates suit zero only; a start
  // away from it is costed with the rates the gyro reads (practice3/T06: from the nominal
  // rates the true moments, a start of the grid, cost more than zero on every flight).
  std::vector<Trial> trials;
  const bool neutral_at_zero = describe(setup.effect).neutral_at_zero;
  const std::vector<Eigen::VectorXd> read_rates =
      neutral_at_zero ? rates_read_at_reference(setup) : std::vector<Eigen::VectorXd>{};
  for (const Eigen::VectorXd& start : grid.starts()) {
    const bool away = neutral_at_zero && !start.isZero();
    trials.push_back({trials.size(), 0.0, start, away ? read_rates : rates});
  }
  grid_costs(setup, problem, trials);
  // The first of equal costs: the grid's order, not the last bits, breaks a tie.
  const Trial& best = *std::min_element(trials.begin(), trials.end(),
                                        [](const Trial& a, const Trial& b) { return a.cost < b.cost; });
  Refined chosen{minimise(problem, best.theta, best.rates, solution_options(setup)), 0.0};
  std::optional<Refined> other =
      other_grid_minimum(problem, trials, best, chosen.result.shared, grid, solution_options(setup));
  return keep_lower(setup, p, std::move(chosen), std::move(other));
}

}  // namespace aloft::host::diagnose
