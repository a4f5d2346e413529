#include "diagnose/4_judge/between_flight_scatter.hpp"

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <algorithm>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "common/printf_text.hpp"
#include "diagnose/4_judge/tensor_intervals.hpp"

namespace aloft::host::diagnose {
namespace {

const Candidate* own_candidate(const Analysis& a, Effect effect) {
  for (const Candidate& c : a.candidates) {
    if (c.effect == effect && c.base.empty() && c.evaluated) return &c;
  }
  return nullptr;
}

// The scatter of the flights' own estimates `theta` (their covariances `covariance`
// widened already) about their precision-weighted mean; none for fewer than 3.
std::optional<BetweenFlightScatter> scatter_of(Effect effect, std::vector<Eigen::VectorXd> theta,
                                               std::vector<Eigen::MatrixXd> covariance) {
  const int n = static_cast<int>(theta.size());
  if (n < 3) return std::nullopt;
  // Where the physics shares only part of the effect (a wheel's axis, not its speed), that
  // part, with its own degrees of freedom.
  Eigen::Index p = theta.front().size();
  if (const auto part_of = describe(effect).shared_part) {
    for (std::size_t j = 0; j < theta.size(); ++j) {
      Eigen::VectorXd part;
      Eigen::MatrixXd part_covariance;
      p = part_of(theta[j], covariance[j], part, part_covariance);
      if (p == 0) return std::nullopt;
      theta[j] = part;
      covariance[j] = part_covariance;
    }
    // A part with fewer degrees of freedom than entries (a unit axis: 2 of 3) is compared
    // in the p directions it moves in: those across the parts' mean, where each part's
    // covariance is full; along the mean it is zero up to rounding, which a pseudo-inverse
    // would read as a precision of 1e20.
    if (p < theta.front().size()) {
      Eigen::VectorXd mean = Eigen::VectorXd::Zero(theta.front().size());
      for (const Eigen::VectorXd& t : theta) mean += t;
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Eigen::MatrixXd(mean.normalized().transpose()),
                                                  Eigen::ComputeFullV);
      const Eigen::MatrixXd across = svd.matrixV().rightCols(p);
      for (std::size_t j = 0; j < theta.size(); ++j) {
        theta[j] = across.transpose() * theta[j];
        covariance[j] = across.transpose() * covariance[j] * across;
      }
    }
  }
  std::vector<Eigen::MatrixXd> precision;
  Eigen::MatrixXd weight = Eigen::MatrixXd::Zero(p, p);
  Eigen::VectorXd weighted = Eigen::VectorXd::Zero(p);
  for (int j = 0; j < n; ++j) {
    precision.push_back(
        covariance[static_cast<std::size_t>(j)].completeOrthogonalDecomposition().pseudoInverse());
    weight += precision.back();
    weighted += precision.back() * theta[static_cast<std::size_t>(j)];
  }
  const Eigen::VectorXd mean = weight.completeOrthogonalDecomposition().solve(weighted);
  double chi_square = 0.0;
  for (int j = 0; j < n; ++j) {
    const Eigen::VectorXd d = theta[static_cast<std::size_t>(j)] - mean;
    chi_square += d.dot(precision[static_cast<std::size_t>(j)] * d);
  }
  BetweenFlightScatter out;
  out.effect = effect;
  out.flights = n;
  out.chi_square_per_dof = chi_square / (static_cast<double>(n - 1) * static_cast<double>(p));
  return out;
}

// The flights' own fits of `effect`, each covariance widened by its flight's noise
// correlation and by `serial_of(j, candidate)`.
template <typename SerialFactor>
std::optional<BetweenFlightScatter> own_fits_scatter(Effect effect, const std::vector<const Analysis*>& own,
                                                     SerialFactor serial_of) {
  std::vector<Eigen::VectorXd> theta;
  std::vector<Eigen::MatrixXd> covariance;
  std::vector<double> shrinks;
  for (std::size_t j = 0; j < own.size(); ++j) {
    const Analysis* a = own[j];
    const Candidate* c = a ? own_candidate(*a, effect) : nullptr;
    if (!c || c->fit.theta_covariance.rows() != c->fit.theta.size() || c->fit.theta.size() == 0) continue;
    theta.push_back(c->fit.theta);
    covariance.push_back(c->fit.theta_covariance * a->where.noise_correlation * serial_of(j, *c));
    shrinks.push_back(c->shrink);
  }
  std::optional<BetweenFlightScatter> out = scatter_of(effect, theta, covariance);
  if (!out) return out;
  const std::size_t n = shrinks.size();
  std::nth_element(shrinks.begin(), shrinks.begin() + static_cast<std::ptrdiff_t>(n / 2), shrinks.end());
  out->median_own_shrink = shrinks[n / 2];
  return out;
}

}  // namespace

std::optional<BetweenFlightScatter> between_flight_scatter(Effect effect,
                                                           const std::vector<const Analysis*>& flights) {
  return own_fits_scatter(effect, flights, [](std::size_t, const Candidate&) { return 1.0; });
}

std::optional<BetweenFlightScatter> between_flight_scatter_serial(Effect effect,
                                                                  const std::vector<const Analysis*>& own,
                                                                  const std::vector<const Flight*>& flights) {
  return own_fits_scatter(
      effect, own, [&](std::size_t j, const Candidate& c) { return serial_inflation(c, {flights.at(j)}); });
}

std::optional<BetweenFlightScatter> between_flight_scatter(const Candidate& candidate,
                                                           const std::vector<const Analysis*>& flights) {
  if (candidate.base.empty() && candidate.flights_own_fits.empty())
    return between_flight_scatter(candidate.effect, flights);
  std::vector<Eigen::VectorXd> theta;
  std::vector<Eigen::MatrixXd> covariance;
  for (std::size_t j = 0; j < candidate.flights_own_fits.size() && j < flights.size(); ++j) {
    const OwnFit& own = candidate.flights_own_fits[j];
    if (own.theta.size() == 0 || own.covariance.rows() != own.theta.size() || !own.theta.allFinite())
      continue;
    theta.push_back(own.theta);
    covariance.push_back(own.covariance * flights[j]->where.noise_correlation);
  }
  return scatter_of(candidate.effect, theta, covariance);
}

std::string between_flight_scatter_note(const BetweenFlightScatter& s, double pooled_shrink,
                                        const std::optional<BetweenFlightScatter>& serial) {
  std::string allowing;
  if (serial) {
    allowing = printf_text(
                   "; allowing for each flight's serially correlated misfit (AR(1) of its own held-out "
                   "residuals, as the tensor report widens its intervals) they scatter %.3g x, ",
                   serial->chi_square_per_dof) +
               (serial->chi_square_per_dof <= kFlightsDisagree
                    ? "so the flights agree on it and what the shared model misses is a misfit of each "
                      "flight's own"
                    : "so the flights truly disagree on it");
  }
  return printf_text("the pooled model shrinks the held-out gap by %.0f %%, its flights' own fits of ",
                     100.0 * pooled_shrink) +
         effect_name(s.effect) +
         printf_text(
             " by %.0f %% (median of %.0f): their parameters scatter %.3g x beyond their own "
             "uncertainty",
             100.0 * s.median_own_shrink, static_cast<double>(s.flights), s.chi_square_per_dof) +
         " (chi-square per degree of freedom between flights; 1 if they shared one value), and a model "
         "shared "
         "by every flight, judged on the flight it left out, cannot follow each" +
         allowing;
}

void note_between_flight_scatter(Analysis& pooled, const std::vector<const Analysis*>& own,
                                 const std::vector<const Flight*>& flights) {
  const Verdict& v = pooled.verdict;
  if (v.effect == Effect::none || !(v.heldout_rms_rel_err_before > 0.0)) return;
  const std::optional<BetweenFlightScatter> scatter = between_flight_scatter(v.effect, own);
  if (!scatter) return;
  const double pooled_shrink = 1.0 - v.heldout_rms_rel_err_after / v.heldout_rms_rel_err_before;
  if (pooled_shrink >= kPooledFallsShort * scatter->median_own_shrink ||
      scatter->chi_square_per_dof <= kFlightsDisagree) {
    return;
  }
  const std::optional<BetweenFlightScatter> serial =
      flights.size() == own.size() ? between_flight_scatter_serial(v.effect, own, flights) : std::nullopt;
  pooled.notes.push_back(between_flight_scatter_note(*scatter, pooled_shrink, serial));
}

}  // namespace aloft::host::diagnose
