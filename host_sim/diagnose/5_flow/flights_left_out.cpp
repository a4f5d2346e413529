#include "diagnose/5_flow/flights_left_out.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/parallel_for.hpp"
#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/4_judge/tensor_intervals.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

// The median over flights of each parameter of the flights' own fits of `effect`.
std::optional<Eigen::VectorXd> median_of_flights(Effect effect, const std::vector<const Analysis*>& own) {
  std::vector<Eigen::VectorXd> thetas;
  for (const Analysis* a : own) {
    const Candidate* c = evaluated_candidate(*a, effect);
    if (c != nullptr && c->fit.theta.allFinite()) thetas.push_back(c->fit.theta);
  }
  if (thetas.empty()) return std::nullopt;
  Eigen::VectorXd median(thetas.front().size());
  for (Eigen::Index i = 0; i < median.size(); ++i) {
    std::vector<double> values;
    for (const Eigen::VectorXd& t : thetas) values.push_back(t(i));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2),
                     values.end());
    median(i) = values[values.size() / 2];
  }
  return median;
}

// A spin-up fitted with each flight's own profile (FlightState::own): each flight's.
void add_flights_own(EffectParameters& p, const EffectFit& fit, const NominalInertia& nominal) {
  if (!p.spin_up || fit.flights.empty() || fit.flights.front().own.size() == 0) return;
  for (std::size_t j = 0; j < fit.flights.size(); ++j) {
    const EffectParameters own = effect_parameters(model_of(fit, nominal, j), flight_theta(fit, j));
    p.spin_up_flights.push_back({own.vector, own.spin_up_profile, 0.0, std::nullopt});
  }
}

}  // namespace

const Candidate* evaluated_candidate(const Analysis& analysis, Effect effect) {
  for (const Candidate& c : analysis.candidates) {
    if (c.effect == effect && c.evaluated) return &c;
  }
  return nullptr;
}

Candidate FlightsLeftOut::nominal_model() const {
  Candidate c;
  c.effect = Effect::none;
  c.fit = none_all_;
  std::vector<GapSums> sums(flights_.size());
  for (std::size_t j = 0; j < flights_.size(); ++j) {
    const Flight& flight = *flights_.flights[j];
    const std::vector<Vec3>& heldout = evaluated_candidate(*own_[j], Effect::none)->heldout_readings.front();
    for (std::size_t k = 0; k < flight.size(); ++k) {
      if (flight.usable[k]) sums[j].add(heldout[k], flight.omega[k], flights_.inverse_sigma[j]);
    }
    c.heldout_readings.push_back(heldout);
    c.heldout_theta.push_back(Eigen::VectorXd());
  }
  set_heldout_gap(c, sums);
  return c;
}

// The shared effect fitted to every flight, started from nominal and from the median of
// the flights' own estimates: a pool of flights that each find the effect must not lose it
// because a start from nominal fell into another basin. The lower cost wins.
EffectFit FlightsLeftOut::fit_pooled(Effect effect) const {
  EffectFit best = fit_effect(effect, nominal_, flights_.all, &none_all_, nullptr, threads_);
  const std::optional<Eigen::VectorXd> median = median_of_flights(effect, own_);
  if (median && !median->isZero()) {
    EffectFit seeded = fit_effect(effect, nominal_, flights_.all, &none_all_, &*median, threads_);
    if (seeded.cost < best.cost) best = std::move(seeded);
  }
  return best;
}

// Leave one flight out: the effect from every flight but j, then flight j's initial rate
// on one fold of its samples, judged on the other.
void FlightsLeftOut::judge_leaving_flights_out(Candidate& c) const {
  const std::size_t count = flights_.size();
  c.heldout_readings.assign(count, {});
  std::vector<GapSums> sums(count);
  c.heldout_theta = leave_one_flight_out(c.fit, nominal_, flights_.all, threads_);
  parallel_for(count, threads_, [&](std::size_t j) {
    EffectFit others = c.fit;
    others.theta = c.heldout_theta[j];
    EffectFit none_j;
    none_j.effect = Effect::none;
    none_j.flights = {none_all_.flights[j]};
    c.heldout_readings[j] = flights_.judge_folds(
        j, nominal_,
        [&](std::size_t f) {
          return fit_initial_rates_near(others, nominal_, flights_.train[j][f], c.fit, j, &none_j);
        },
        sums[j]);
  });
  set_heldout_gap(c, sums);
}

// Each flight's own fit of c's model (its base and its effect together), started from
// the pooled fit; the effect's part of it (told_apart.hpp).
std::vector<OwnFit> FlightsLeftOut::fit_each_flight(const Candidate& base, const Candidate& c) const {
  std::vector<OwnFit> out(flights_.size());
  const int count = effect_parameter_count(c.effect);
  parallel_for(flights_.size(), threads_, [&](std::size_t j) {
    EffectFit base_j = base.fit;
    base_j.flights = {base.fit.flights[j]};
    const EffectFit fit = fit_added_effect(base_j, c.effect, nominal_, {flights_.all[j]},
                                           &flight_theta(c.fit, j), 1, SecondStart::readings_when_seeded);
    const int offset = theta_offset(model_of(fit, nominal_, 0), c.effect);
    if (offset < 0 || offset + count > fit.theta.size() || fit.theta_covariance.rows() != fit.theta.size())
      return;
    out[j].theta = fit.theta.segment(offset, count);
    out[j].covariance = fit.theta_covariance.block(offset, offset, count, count);
  });
  return out;
}

Candidate FlightsLeftOut::evaluate(const Candidate& base, Effect added) const {
  Candidate c;
  c.effect = added;
  c.base = model_effects(model_of(base.fit, nominal_, 0));
  if (!describe(added).shared_by_flights) {
    c.evaluated = false;
    c.note = "per flight only: an impulse is not shared by the flights of a session";
    return c;
  }
  c.fit = c.base.empty() ? fit_pooled(added)
                         : fit_added_effect(base.fit, added, nominal_, flights_.all, nullptr, threads_,
                                            SecondStart::base_at_nominal);
  c.params = effect_parameters(model_of(c.fit, nominal_, 0), c.fit.theta);
  add_flights_own(c.params, c.fit, nominal_);
  judge_leaving_flights_out(c);
  // On a base, or a variant (its flights' own analyses did not all try it): each
  // flight's own fit, for the agreement test of told_apart.hpp.
  if (describe(added).named_only_when_told_apart &&
      (!c.base.empty() || describe(added).variant_of != Effect::none))
    c.flights_own_fits = fit_each_flight(base, c);
  if (!std::isfinite(c.heldout_rms_rel_err)) {
    // Leaving a flight out of a nearly degenerate joint fit (two effects the pool can
    // hardly tell apart) can throw its parameters anywhere: no verdict from that.
    c.evaluated = false;
    c.note = "the joint fit is degenerate here: leaving a flight out makes it diverge";
  }
  return c;
}

bool FlightsLeftOut::tensor_report(const Analysis& analysis, TensorReport& report) const {
  return pooled_tensor_report(analysis, flights_.flights, nominal_, report);
}

}  // namespace aloft::host::diagnose
