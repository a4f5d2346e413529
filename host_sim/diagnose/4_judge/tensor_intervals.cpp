#include "diagnose/4_judge/tensor_intervals.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/3_fit/effect_fit.hpp"

namespace aloft::host::diagnose {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;
constexpr double kNormal975 = 1.959964;
constexpr double kChiSquare3At95 = 7.814728;  // a 95 % region of a 3-vector

// Student's t 0.975 quantile on `dof` degrees of freedom (table, then the normal limit).
double student_t_975(int dof) {
  static const std::array<double, 30> table = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306,
                                               2.262,  2.228, 2.201, 2.179, 2.160, 2.145, 2.131, 2.120,
                                               2.110,  2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064,
                                               2.060,  2.056, 2.052, 2.048, 2.045, 2.042};
  if (dof < 1) return table[0];
  return dof <= 30 ? table[static_cast<std::size_t>(dof - 1)] : kNormal975 + 2.4 / dof;
}

const Candidate* find(const Analysis& a, Effect e) {
  for (const Candidate& c : a.candidates) {
    if (c.effect == e && c.evaluated) return &c;
  }
  return nullptr;
}

// The moments as one candidate fitted them: their principal values (nominal principal
// order), the covariance of their two free log parameters, and (a session) those two
// fitted without each flight.
struct MomentsFit {
  const Candidate* candidate = nullptr;
  Eigen::Vector3d principal_kg_m2 = Eigen::Vector3d::Zero();
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  std::vector<Eigen::Vector2d> heldout;
};

// Where the final model holds an effect that the moments take up when fitted alone (its
// descriptor's `jointly_with`: a rotor) and not the moments themselves, the moments fitted
// beside it: the last step tried the final model with each effect added, and added none.
// Not beside an effect with each flight's own parameters (`flight_own`: a spun-up wheel's
// timing), which a fit on a base shares across flights (FitSetup::own): that fit is not
// the model the verdict names (a withheld spin-up session's moments read beside it held
// out 7.8 times worse than the wheel alone, and the tensor report lost the moment error).
const Candidate* moments_beside_final_model(const Analysis& a) {
  if (a.steps.empty() || a.steps.back().added >= 0) return nullptr;
  std::vector<Effect> model = a.model.base;
  model.push_back(a.model.effect);
  const bool takes_up = std::any_of(model.begin(), model.end(), [](Effect e) {
    return describe(e).jointly_with == Effect::inertia_moments && describe(e).flight_own.count == 0;
  });
  if (!takes_up || std::find(model.begin(), model.end(), Effect::inertia_moments) != model.end())
    return nullptr;
  for (const Candidate& c : a.steps.back().candidates) {
    if (c.effect == Effect::inertia_moments && !c.reference && c.evaluated) return &c;
  }
  return nullptr;
}

// The candidate the moments are read from. Fitted alone, the moments take up part of what
// a rotor does (test_internal_momentum.cpp: 2 to 98 % off the true ratios in rotor
// sessions), so: the first step's pair where one that holds the moments joined the model
// (4_judge/joint_candidates.hpp: a rotor beside wrong moments); the moments beside the
// final model where it holds a rotor alone; else the moments fitted alone. Nothing when
// none has a covariance of the moments.
std::optional<MomentsFit> moments_fit(const Analysis& a, const NominalInertia& nominal) {
  const Candidate* c = find(a, Effect::inertia_moments);
  if (const int pair = first_step_pair_holding(a, Effect::inertia_moments); pair >= 0)
    c = &a.candidates[static_cast<std::size_t>(pair)];
  if (const Candidate* beside = moments_beside_final_model(a)) c = beside;
  if (c == nullptr || c->fit.flights.empty()) return std::nullopt;
  const EffectModel model = model_of(c->fit, nominal, 0);
  const int at = theta_offset(model, Effect::inertia_moments);
  if (at < 0 || c->fit.theta_covariance.rows() < at + 2) return std::nullopt;
  MomentsFit m;
  m.candidate = c;
  m.principal_kg_m2 = c->effect == Effect::inertia_moments
                          ? c->params.principal_kg_m2
                          : effect_parameters(model, c->fit.theta, Effect::inertia_moments).principal_kg_m2;
  m.covariance = c->fit.theta_covariance.block<2, 2>(at, at);
  for (const Eigen::VectorXd& t : c->heldout_theta) m.heldout.push_back(t.segment<2>(at));
  return m;
}

// d(log moment k)/d(theta) for the ascending principal moments (flight_model.hpp: u0, u1
// free, u2 = -u0 - u1; the rescaling to the nominal sum cancels in every ratio).
Eigen::RowVector2d log_moment_gradient(int k) {
  if (k == 0) return Eigen::RowVector2d(1.0, 0.0);
  if (k == 1) return Eigen::RowVector2d(0.0, 1.0);
  return Eigen::RowVector2d(-1.0, -1.0);
}

// Rows: d(log ratio)/d(theta) of I2/I1 and I3/I1 in body file order.
Eigen::Matrix2d log_ratio_gradient(const Eigen::Vector3i& order) {
  Eigen::Matrix2d g;
  g.row(0) = log_moment_gradient(order(1)) - log_moment_gradient(order(0));
  g.row(1) = log_moment_gradient(order(2)) - log_moment_gradient(order(0));
  return g;
}

Eigen::Vector2d ratios_of(const Eigen::Vector3d& moments, const Eigen::Vector3i& order) {
  return Eigen::Vector2d(moments(order(1)) / moments(order(0)), moments(order(2)) / moments(order(0)));
}

TensorReport base_report(const MomentsFit& moments, const NominalInertia& nominal) {
  TensorReport r;
  r.axis_order = principal_axis_order(nominal);
  r.ratio_best = ratios_of(moments.principal_kg_m2, r.axis_order);
  r.ratio_nominal = ratios_of(nominal.principal_moments, r.axis_order);
  return r;
}

// Intervals from the log ratios' standard errors and a quantile.
void set_intervals(TensorReport& r, const Eigen::Vector2d& log_se, double quantile) {
  for (int i = 0; i < 2; ++i) {
    r.ratio_low(i) = r.ratio_best(i) * std::exp(-quantile * log_se(i));
    r.ratio_high(i) = r.ratio_best(i) * std::exp(quantile * log_se(i));
  }
  r.consistent_with_nominal = true;
  for (int i = 0; i < 2; ++i) {
    r.consistent_with_nominal = r.consistent_with_nominal && r.ratio_nominal(i) >= r.ratio_low(i) &&
                                r.ratio_nominal(i) <= r.ratio_high(i);
  }
}

// The pairs of body axes whose moments' ratio has a 95 % interval holding 1, from the
// log ratios' covariance (body order: log I2/I1, log I3/I1) and the interval's quantile.
void find_unresolved_planes(TensorReport& r, const MomentsFit& moments, const Eigen::Matrix2d& log_cov,
                            double quantile) {
  const Eigen::Vector2d l(std::log(r.ratio_best(0)), std::log(r.ratio_best(1)));
  struct Pair {
    int a, b;
    double log_ratio, variance;
  };
  const Pair pairs[] = {{0, 1, l(0), log_cov(0, 0)},
                        {0, 2, l(1), log_cov(1, 1)},
                        {1, 2, l(1) - l(0), log_cov(0, 0) + log_cov(1, 1) - 2.0 * log_cov(0, 1)}};
  for (const Pair& p : pairs) {
    if (std::abs(p.log_ratio) <= quantile * std::sqrt(std::max(p.variance, 0.0)))
      r.unresolved_planes.push_back({p.a, p.b});
  }
  for (int b = 0; b < 3; ++b) r.moments_kg_m2(b) = moments.principal_kg_m2(r.axis_order(b));
}

// The axes bound: the fitted rotation plus the 95 % radius of its error ellipsoid. None
// where two moments are not told apart: a rotation within their plane changes nothing.
void set_axes(TensorReport& r, const Candidate* axes, const Eigen::Matrix3d& covariance, double widen) {
  if (axes == nullptr || !r.unresolved_planes.empty()) return;
  const double largest =
      std::max(0.0, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvalues().maxCoeff());
  r.axes_95_deg = axes->params.angle_deg + widen * std::sqrt(kChiSquare3At95 * largest) * kDeg;
  r.axes_known = std::isfinite(r.axes_95_deg);
}

Eigen::Matrix3d model_covariance_3(const Candidate& c, double inflation) {
  if (c.fit.theta_covariance.rows() != 3) return Eigen::Matrix3d::Zero();
  return Eigen::Matrix3d(c.fit.theta_covariance) * inflation;
}

}  // namespace

double serial_inflation(const Candidate& c, const std::vector<const Flight*>& flights) {
  double product = 0.0, square = 0.0;
  for (std::size_t f = 0; f < flights.size() && f < c.heldout_readings.size(); ++f) {
    const Flight& flight = *flights[f];
    const auto& p = c.heldout_readings[f];
    for (std::size_t k = 0; k + 1 < flight.size() && k + 1 < p.size(); ++k) {
      if (!flight.usable[k] || !flight.usable[k + 1]) continue;
      const Eigen::Vector3d a = p[k] - flight.omega[k], b = p[k + 1] - flight.omega[k + 1];
      product += a.dot(b);
      square += a.squaredNorm();
    }
  }
  const double rho = square > 0.0 ? std::clamp(product / square, 0.0, 0.95) : 0.0;
  return (1.0 + rho) / (1.0 - rho);
}

bool flight_tensor_report(const Analysis& analysis, const std::vector<const Flight*>& flights,
                          const NominalInertia& nominal, TensorReport& report) {
  const std::optional<MomentsFit> moments = moments_fit(analysis, nominal);
  if (!moments) return false;
  TensorReport r = base_report(*moments, nominal);
  const double inflation = serial_inflation(*moments->candidate, flights);
  const Eigen::Matrix2d g = log_ratio_gradient(r.axis_order);
  const Eigen::Matrix2d cov = g * moments->covariance * g.transpose() * inflation;
  set_intervals(r, cov.diagonal().cwiseMax(0.0).cwiseSqrt(), kNormal975);
  find_unresolved_planes(r, *moments, cov, kNormal975);
  const Candidate* axes = find(analysis, Effect::inertia_axes);
  if (axes != nullptr) set_axes(r, axes, model_covariance_3(*axes, serial_inflation(*axes, flights)), 1.0);
  r.flights = static_cast<int>(flights.size());
  r.method = "fit covariance (noise from the residuals), widened for their serial correlation";
  report = r;
  return true;
}

bool pooled_tensor_report(const Analysis& pooled, const std::vector<const Flight*>& flights,
                          const NominalInertia& nominal, TensorReport& report) {
  const std::optional<MomentsFit> moments = moments_fit(pooled, nominal);
  const std::size_t n = flights.size();
  if (!moments || moments->heldout.size() != n || n < 2) return false;
  TensorReport r = base_report(*moments, nominal);
  const Eigen::Matrix2d g = log_ratio_gradient(r.axis_order);
  const Eigen::Matrix2d model =
      g * moments->covariance * g.transpose() * serial_inflation(*moments->candidate, flights);
  // Jackknife over flights: (n-1)/n times the spread of the leave-one-out estimates.
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& t : moments->heldout) mean += g * t;
  mean /= static_cast<double>(n);
  Eigen::Vector2d spread = Eigen::Vector2d::Zero();
  for (const Eigen::Vector2d& t : moments->heldout) spread += (g * t - mean).cwiseAbs2();
  const Eigen::Vector2d jackknife = spread * (static_cast<double>(n) - 1.0) / static_cast<double>(n);
  const double t = student_t_975(static_cast<int>(n) - 1);
  const Eigen::Vector2d variance = jackknife.cwiseMax(model.diagonal().cwiseMax(0.0));
  set_intervals(r, variance.cwiseSqrt(), t);
  // The covariance of the two log ratios: the wider of the jackknife and the fit on the
  // diagonal, the fit's correlation between them.
  const double correlation = model(0, 1) / std::sqrt(std::max(model(0, 0) * model(1, 1), 1e-300));
  Eigen::Matrix2d log_cov = variance.asDiagonal();
  log_cov(0, 1) = log_cov(1, 0) = correlation * std::sqrt(variance(0) * variance(1));
  find_unresolved_planes(r, *moments, log_cov, t);

  const Candidate* axes = find(pooled, Effect::inertia_axes);
  if (axes != nullptr && axes->heldout_theta.size() == n) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (const Eigen::VectorXd& d : axes->heldout_theta) centre += d.head<3>();
    centre /= static_cast<double>(n);
    Eigen::Matrix3d jack = Eigen::Matrix3d::Zero();
    for (const Eigen::VectorXd& d : axes->heldout_theta)
      jack += (d.head<3>() - centre) * (d.head<3>() - centre).transpose();
    jack *= (static_cast<double>(n) - 1.0) / static_cast<double>(n);
    const Eigen::Matrix3d own = model_covariance_3(*axes, serial_inflation(*axes, flights));
    const double jl = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(jack).eigenvalues().maxCoeff();
    const double ol = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(own).eigenvalues().maxCoeff();
    set_axes(r, axes, jl > ol ? jack : own, t / kNormal975);
  }
  r.flights = static_cast<int>(n);
  r.method = "jackknife over flights (Student t, n-1 dof), never narrower than the pooled fit's covariance";
  report = r;
  return true;
}

}  // namespace aloft::host::diagnose
