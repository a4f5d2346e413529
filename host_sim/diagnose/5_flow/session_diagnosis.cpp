// The pooled analysis of a session (SPEC §4 with --segments): every effect except the
// impulse (a knock belongs to one flight) is shared by all flights, each flight keeping
// its own initial rate. Held out: leave one flight out. The effect is fitted to the other
// flights (one Gauss-Newton step from the all-flights solution, effect_fit.hpp); on the
// left-out flight only the initial rate is fitted, on one fold of its samples, and the gap
// is judged on the other fold (and the other way round), so that no sample is ever judged
// by a fit that saw it. Compound models come from the same stepwise selection as a
// flight's (stepwise_selection.hpp), with this held-out rule as its evaluator.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include "common/parallel_for.hpp"
#include "diagnose/3_fit/held_out.hpp"
#include "diagnose/4_judge/baseline_gap.hpp"
#include "diagnose/4_judge/candidate_ranking.hpp"
#include "diagnose/4_judge/confidence.hpp"
#include "diagnose/4_judge/plausibility.hpp"
#include "diagnose/4_judge/stepwise_selection.hpp"
#include "diagnose/4_judge/tensor_intervals.hpp"
#include "diagnose/5_flow/diagnosis.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

struct PooledData {
  std::vector<const Flight*> flights;
  std::vector<Vec3> inverse_sigma;
  std::vector<FlightData> all;                   // every sample of every flight
  std::vector<std::array<FlightData, 2>> train;  // fold training masks per flight
  std::vector<Folds> folds;
  std::vector<const Analysis*> own;  // each flight's own analysis
};

const Candidate* candidate_of(const Analysis& a, Effect effect) {
  for (const Candidate& c : a.candidates) {
    if (c.effect == effect && c.evaluated) return &c;
  }
  return nullptr;
}

// The nominal fits of the flights' own analyses as one fit of the pooled flights.
EffectFit per_flight_nominal_fit(const PooledData& pool) {
  EffectFit fit;
  fit.effect = Effect::none;
  for (const Analysis* a : pool.own) {
    const EffectFit& own = candidate_of(*a, Effect::none)->fit;
    fit.flights.push_back(own.flights.front());
    fit.cost += own.cost;
    fit.residual_count += own.residual_count;
  }
  return fit;
}

void fill_heldout_figures(Candidate& c, const std::vector<GapSums>& sums) {
  GapSums total;
  for (const GapSums& s : sums) {
    total.chi_square += s.chi_square;
    total.residuals += s.residuals;
    total.da_sq += s.da_sq;
    total.rel_sq += s.rel_sq;
    total.samples += s.samples;
  }
  c.heldout_chi_square = total.chi_square;
  c.heldout_residuals = total.residuals;
  c.heldout_rms_da_deg = total.rms_da_deg();
  c.heldout_rms_rel_err = total.rms_rel_err();
}

// The nominal model pooled: each flight's own nominal fit and its own held-out
// predictions (nothing is shared, so leaving a flight out changes nothing), so the pooled
// baseline is the flights' baselines put together.
Candidate nominal_candidate(const PooledData& pool, const EffectFit& none_all) {
  Candidate c;
  c.effect = Effect::none;
  c.fit = none_all;
  std::vector<GapSums> sums(pool.flights.size());
  for (std::size_t j = 0; j < pool.flights.size(); ++j) {
    const Flight& flight = *pool.flights[j];
    const std::vector<Vec3>& heldout = candidate_of(*pool.own[j], Effect::none)->heldout_readings.front();
    for (std::size_t k = 0; k < flight.size(); ++k) {
      if (flight.usable[k]) sums[j].add(heldout[k], flight.omega[k], pool.inverse_sigma[j]);
    }
    c.heldout_readings.push_back(heldout);
    c.heldout_theta.push_back(Eigen::VectorXd());
  }
  fill_heldout_figures(c, sums);
  return c;
}

// The median over flights of each parameter of the flights' own fits of `effect`.
std::optional<Eigen::VectorXd> median_of_flights(Effect effect, const PooledData& pool) {
  std::vector<Eigen::VectorXd> thetas;
  for (const Analysis* a : pool.own) {
    const Candidate* c = candidate_of(*a, effect);
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

// The shared effect fitted to every flight, started from nominal and from the median of
// the flights' own estimates: a pool of flights that each find the effect must not lose it
// because a start from nominal fell into another basin. The lower cost wins.
EffectFit fit_pooled(Effect effect, const NominalInertia& nominal, const PooledData& pool,
                     const EffectFit& none_all, unsigned threads) {
  EffectFit best = fit_effect(effect, nominal, pool.all, &none_all, nullptr, threads);
  const std::optional<Eigen::VectorXd> median = median_of_flights(effect, pool);
  if (median && !median->isZero()) {
    EffectFit seeded = fit_effect(effect, nominal, pool.all, &none_all, &*median, threads);
    if (seeded.cost < best.cost) best = std::move(seeded);
  }
  return best;
}

// Leave one flight out: the effect from every flight but j, then flight j's initial rate
// on one fold of its samples, judged on the other.
void judge_leaving_flights_out(Candidate& c, const NominalInertia& nominal, const PooledData& pool,
                               const EffectFit& none_all, int threads) {
  const std::size_t count = pool.flights.size();
  c.heldout_readings.assign(count, {});
  std::vector<GapSums> sums(count);
  c.heldout_theta =
      leave_one_flight_out(c.fit, nominal, pool.all, static_cast<unsigned>(std::max(threads, 1)));
  parallel_for(count, static_cast<unsigned>(std::max(threads, 1)), [&](std::size_t j) {
    EffectFit others = c.fit;
    others.theta = c.heldout_theta[j];
    const Flight& flight = *pool.flights[j];
    std::vector<Vec3> heldout(flight.size(), Vec3::Zero());
    std::vector<Vec3> readings;
    EffectFit none_j;
    none_j.effect = Effect::none;
    none_j.flights = {none_all.flights[j]};
    for (std::size_t f = 0; f < 2; ++f) {
      const EffectFit rates = fit_initial_rates(others, nominal, {pool.train[j][f]}, &none_j);
      predict(rates, nominal, 0, flight, readings);
      for (std::size_t k = 0; k < flight.size(); ++k) {
        if (!pool.folds[j].judge[f][k]) continue;
        heldout[k] = readings[k];
        if (flight.usable[k]) sums[j].add(readings[k], flight.omega[k], pool.inverse_sigma[j]);
      }
    }
    c.heldout_readings[j] = std::move(heldout);
  });
  fill_heldout_figures(c, sums);
}

// Where most flights agree on an effect and the pool does not, which flights disagree
// (and where the pool agrees, which flights name something else).
void note_disagreeing_flights(Analysis& pooled, const PooledData& pool) {
  std::vector<Effect> named;
  for (const Analysis* a : pool.own) named.push_back(a->verdict.effect);
  Effect majority = Effect::none;
  std::size_t most = 0;
  for (Effect e : named) {
    const std::size_t votes = static_cast<std::size_t>(std::count(named.begin(), named.end(), e));
    if (votes > most) {
      most = votes;
      majority = e;
    }
  }
  const std::vector<Effect>& same = pooled.verdict.equivalent;
  const bool pool_agrees = std::find(same.begin(), same.end(), majority) != same.end();
  std::string names;
  for (std::size_t j = 0; j < pool.flights.size(); ++j) {
    const Effect own = pool.own[j]->verdict.effect;
    if (std::find(same.begin(), same.end(), own) != same.end()) continue;
    names += (names.empty() ? "" : ", ") + pool.flights[j]->name + " (" + effect_name(own) + ")";
  }
  if (names.empty()) return;
  if (!pool_agrees && 2 * most > named.size()) {
    pooled.notes.push_back(std::to_string(most) + " of " + std::to_string(named.size()) + " flights name " +
                           effect_name(majority) +
                           " but the pool does not; flights that disagree with the pool: " + names);
  } else {
    pooled.notes.push_back("flights whose own verdict differs from the pool's: " + names);
  }
}

bool mentions_intermediate(const std::string& comment) {
  std::string lower = comment;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower.find("intermediate") != std::string::npos;
}

// Flip periods per flight, nominal and with the pooled final model (its parameters
// fitted without that flight), from the first sample and from the flight's fitted
// initial state under each model (flip_period.hpp).
void add_flip_periods(SessionDiagnosis& session, const PooledData& pool, const EffectFit& none_all,
                      const std::vector<Flight>& flights, const NominalInertia& nominal) {
  const Analysis& a = session.pooled;
  const Candidate* final_model =
      a.verdict.effect != Effect::none && a.model.heldout_theta.size() == pool.flights.size() ? &a.model
                                                                                              : nullptr;
  const EffectModel model = final_model != nullptr ? model_of(final_model->fit, nominal, 0) : EffectModel();
  for (std::size_t i = 0; i < flights.size(); ++i) {
    const auto it = std::find(pool.flights.begin(), pool.flights.end(), &flights[i]);
    if (it == pool.flights.end()) continue;
    const std::size_t j = static_cast<std::size_t>(it - pool.flights.begin());
    const FlightState& nominal_start = none_all.flights[j];
    if (final_model == nullptr) {
      session.flights[i].flip_period =
          flip_period(flights[i], nominal, nullptr, Eigen::VectorXd(), &nominal_start);
      continue;
    }
    EffectFit held = final_model->fit;
    held.theta = final_model->heldout_theta[j];
    EffectFit none_j;
    none_j.flights = {nominal_start};
    const EffectFit start = fit_initial_rates(held, nominal, {pool.all[j]}, &none_j);
    session.flights[i].flip_period =
        flip_period(flights[i], nominal, &model, held.theta, &nominal_start, &start.flights.front());
  }
  bool any_intermediate = false;
  for (const Flight& f : flights) any_intermediate = any_intermediate || mentions_intermediate(f.comment);
  FlipPeriodSummary summary;
  for (std::size_t i = 0; i < flights.size(); ++i) {
    const auto& fp = session.flights[i].flip_period;
    if (!fp || (any_intermediate && !mentions_intermediate(flights[i].comment))) continue;
    ++summary.flights;
    summary.mean_error_nominal += fp->nominal_error();
    if (fp->diagnosed_s) {
      ++summary.diagnosed_flights;
      summary.mean_error_diagnosed += fp->error(*fp->diagnosed_s);
    }
    if (fp->nominal_fitted_s && fp->diagnosed_fitted_s) {
      ++summary.fitted_flights;
      summary.mean_error_nominal_fitted += fp->error(*fp->nominal_fitted_s);
      summary.mean_error_diagnosed_fitted += fp->error(*fp->diagnosed_fitted_s);
    }
  }
  if (summary.flights == 0) return;
  summary.mean_error_nominal /= summary.flights;
  if (summary.diagnosed_flights > 0) summary.mean_error_diagnosed /= summary.diagnosed_flights;
  if (summary.fitted_flights > 0) {
    summary.mean_error_nominal_fitted /= summary.fitted_flights;
    summary.mean_error_diagnosed_fitted /= summary.fitted_flights;
  }
  session.flip_period = summary;
}

// Only flights that could be judged on their own take part in the pooled analysis; the
// others are named in a note.
PooledData pool_judged_flights(SessionDiagnosis& session, const std::vector<Flight>& flights) {
  PooledData pool;
  for (std::size_t i = 0; i < flights.size(); ++i) {
    const FlightDiagnosis& d = session.flights[i];
    if (d.analysis.candidates.empty()) {
      session.pooled.notes.push_back("flight " + d.name + " left out of the pooled analysis: " +
                                     (d.analysis.verdict.could_not_judge.empty()
                                          ? std::string("not judged")
                                          : d.analysis.verdict.could_not_judge.front()));
      continue;
    }
    const Vec3 inv = d.noise.weighting_sigma().cwiseInverse();
    pool.flights.push_back(&flights[i]);
    pool.own.push_back(&d.analysis);
    pool.inverse_sigma.push_back(inv);
    pool.all.push_back(FlightData{&flights[i], all_samples(flights[i].size()), inv});
    pool.folds.push_back(interleaved_folds(flights[i].size()));
    pool.train.push_back({FlightData{&flights[i], pool.folds.back().train[0], inv},
                          FlightData{&flights[i], pool.folds.back().train[1], inv}});
  }
  return pool;
}

// One flight: nothing to pool, so the top level is that flight's own analysis (held out
// within the flight), said so.
void take_single_flight(SessionDiagnosis& session, const PooledData& pool) {
  Analysis& analysis = session.pooled;
  std::vector<std::string> notes = std::move(analysis.notes);
  analysis = *pool.own.front();
  notes.push_back("one judged flight (" + pool.flights.front()->name +
                  "): the top level is that flight's own verdict, held out within the flight");
  analysis.notes.insert(analysis.notes.end(), notes.begin(), notes.end());
  session.single_flight = true;
}

// Baseline and where, pooled over every flight's nominal fit.
void describe_pooled_baseline(Analysis& analysis, const PooledData& pool, const EffectFit& none_all,
                              const NominalInertia& nominal) {
  BaselineGap baseline;
  std::vector<Vec3> readings;
  for (std::size_t f = 0; f < pool.flights.size(); ++f) {
    predict(none_all, nominal, f, *pool.flights[f], readings);
    baseline.add(*pool.flights[f], readings, pool.inverse_sigma[f]);
  }
  baseline.describe(analysis);
}

// What the ranking of pooled candidates needs to know of the pooled flights.
RankingContext pooled_context(const SessionDiagnosis& session, const PooledData& pool,
                              const NominalInertia& nominal) {
  double speed_sum = 0.0, duration_sum = 0.0;
  for (const Flight* f : pool.flights) {
    speed_sum += f->mean_speed();
    duration_sum += f->end_s() - f->start_s();
  }
  // The pooled fit informs shared parameters with every flight's data.
  const double mean_speed = speed_sum / pool.flights.size();
  const double total_duration = duration_sum;

  // The coarsest resolution of the pooled flights (those left out have none).
  double resolution = 0.0;
  for (const FlightDiagnosis& d : session.flights) resolution = std::max(resolution, d.noise.resolution);
  return RankingContext{pool.flights.front()->gyro_input,
                        pool.flights,
                        pool.inverse_sigma,
                        mean_speed,
                        total_duration,
                        &nominal,
                        resolution};
}

// Onset of a session: the median of the flights' onsets, relative to each flight's start.
void set_pooled_onset(SessionDiagnosis& session) {
  Analysis& analysis = session.pooled;
  std::vector<double> onsets;
  for (const FlightDiagnosis& d : session.flights) {
    if (d.analysis.where.onset_s) onsets.push_back(*d.analysis.where.onset_s - d.start_s);
  }
  if (analysis.verdict.effect != Effect::none && !onsets.empty()) {
    std::nth_element(onsets.begin(), onsets.begin() + static_cast<std::ptrdiff_t>(onsets.size() / 2),
                     onsets.end());
    analysis.where.onset_s = onsets[onsets.size() / 2];
    analysis.notes.push_back(
        "pooled where.onset_s is the median over flights, seconds after each flight's start");
  }
}

}  // namespace

SessionDiagnosis diagnose_session(const std::vector<Flight>& flights, const NominalInertia& nominal,
                                  int threads, const ParallelProgress& flights_done) {
  SessionDiagnosis session;
  session.flights.resize(flights.size());
  const unsigned workers = static_cast<unsigned>(std::max(threads, 1));
  parallel_for(
      flights.size(), workers,
      [&](std::size_t i) { session.flights[i] = diagnose_flight(flights[i], nominal); }, flights_done);

  PooledData pool = pool_judged_flights(session, flights);
  Analysis& analysis = session.pooled;
  const std::size_t count = pool.flights.size();
  if (count == 1) {
    take_single_flight(session, pool);
    return session;
  }
  if (count < 2) {
    analysis.verdict.confident = false;
    analysis.verdict.could_not_judge.push_back(
        "fewer than two judged flights: nothing to leave out for a pooled analysis");
    return session;
  }

  // One gap, one definition: the pooled nominal model is every flight's own nominal fit.
  const EffectFit none_all = per_flight_nominal_fit(pool);
  describe_pooled_baseline(analysis, pool, none_all, nominal);
  const RankingContext context = pooled_context(session, pool, nominal);
  // Every model of the search, single or compound: its shared parameters fitted to every
  // flight, judged by leaving one flight out.
  const CandidateEvaluator evaluate = [&](const Candidate& base, Effect added) {
    Candidate c;
    c.effect = added;
    c.base = model_effects(model_of(base.fit, nominal, 0));
    if (added == Effect::impulse) {
      c.evaluated = false;
      c.note = "per flight only: an impulse is not shared by the flights of a session";
      return c;
    }
    c.fit = c.base.empty() ? fit_pooled(added, nominal, pool, none_all, workers)
                           : fit_added_effect(base.fit, added, nominal, pool.all);
    c.params = effect_parameters(model_of(c.fit, nominal, 0), c.fit.theta);
    judge_leaving_flights_out(c, nominal, pool, none_all, threads);
    if (!std::isfinite(c.heldout_rms_rel_err)) {
      // Leaving a flight out of a nearly degenerate joint fit (two effects the pool can
      // hardly tell apart) can throw its parameters anywhere: no verdict from that.
      c.evaluated = false;
      c.note = "the joint fit is degenerate here: leaving a flight out makes it diverge";
    }
    return c;
  };
  const Candidate nominal_model = nominal_candidate(pool, none_all);
  for (Effect effect : candidate_effects(context.gyro_input)) {
    analysis.candidates.push_back(effect == Effect::none ? nominal_model : evaluate(nominal_model, effect));
  }
  rule_out_senseless(analysis.candidates);
  rank_candidates(analysis, context);
  select_stepwise(analysis, context, evaluate);
  TensorReport tensor;
  if (pooled_tensor_report(analysis, pool.flights, nominal, tensor)) analysis.tensor = tensor;
  temper_confidence(analysis);
  note_disagreeing_flights(analysis, pool);
  add_flip_periods(session, pool, none_all, flights, nominal);
  set_pooled_onset(session);
  return session;
}

}  // namespace aloft::host::diagnose
