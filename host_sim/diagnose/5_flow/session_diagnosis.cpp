// The pooled analysis of a session (SPEC §4 with --segments): every flight on its own,
// then the flights judged together by the candidate loop (judge_candidates.hpp) with the
// leave-one-flight-out rule (flights_left_out.hpp). Only flights that could be judged on
// their own take part; with one of them the session is that flight's own analysis.
#include <algorithm>
#include <optional>
#include <string>

#include "common/parallel_for.hpp"
#include "diagnose/4_judge/baseline_gap.hpp"
#include "diagnose/4_judge/between_flight_scatter.hpp"
#include "diagnose/4_judge/flight_agreement.hpp"
#include "diagnose/4_judge/flip_period_summary.hpp"
#include "diagnose/4_judge/onset.hpp"
#include "diagnose/4_judge/spin_up_end.hpp"
#include "diagnose/5_flow/diagnosis.hpp"
#include "diagnose/5_flow/flights_left_out.hpp"
#include "diagnose/5_flow/judge_candidates.hpp"
#include "diagnose/5_flow/judged_flights.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

// The flights judged together, and each one's own analysis.
struct PooledData {
  JudgedFlights judged;
  std::vector<const Analysis*> own;
};

// The nominal fits of the flights' own analyses as one fit of the pooled flights.
EffectFit per_flight_nominal_fit(const PooledData& pool) {
  EffectFit fit;
  fit.effect = Effect::none;
  for (const Analysis* a : pool.own) {
    const EffectFit& own = evaluated_candidate(*a, Effect::none)->fit;
    fit.flights.push_back(own.flights.front());
    fit.cost += own.cost;
    fit.residual_count += own.residual_count;
  }
  return fit;
}

// Flip periods per flight, nominal and with the pooled final model (its parameters
// fitted without that flight), from the first sample and from the flight's fitted
// initial state under each model (flip_period.hpp).
void add_flip_periods(SessionDiagnosis& session, const PooledData& pool, const EffectFit& none_all,
                      const std::vector<Flight>& flights, const NominalInertia& nominal) {
  const Analysis& a = session.pooled;
  const Candidate* final_model =
      a.verdict.effect != Effect::none && a.model.heldout_theta.size() == pool.judged.flights.size()
          ? &a.model
          : nullptr;
  const EffectModel model = final_model != nullptr ? model_of(final_model->fit, nominal, 0) : EffectModel();
  for (std::size_t i = 0; i < flights.size(); ++i) {
    const auto it = std::find(pool.judged.flights.begin(), pool.judged.flights.end(), &flights[i]);
    if (it == pool.judged.flights.end()) continue;
    const std::size_t j = static_cast<std::size_t>(it - pool.judged.flights.begin());
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
    const EffectFit start = fit_initial_rates(held, nominal, {pool.judged.all[j]}, &none_j);
    session.flights[i].flip_period =
        flip_period(flights[i], nominal, &model, held.theta, &nominal_start, &start.flights.front());
  }
  std::vector<std::string> comments;
  std::vector<std::optional<FlipPeriod>> periods;
  for (std::size_t i = 0; i < flights.size(); ++i) {
    comments.push_back(flights[i].comment);
    periods.push_back(session.flights[i].flip_period);
  }
  session.flip_period = summarize_flip_periods(comments, periods);
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
    pool.judged.add(flights[i], d.noise.weighting_sigma().cwiseInverse());
    pool.own.push_back(&d.analysis);
  }
  return pool;
}

// One flight: nothing to pool, so the top level is that flight's own analysis (held out
// within the flight), said so.
void take_single_flight(SessionDiagnosis& session, const PooledData& pool) {
  Analysis& analysis = session.pooled;
  std::vector<Note> notes = std::move(analysis.notes);
  analysis = *pool.own.front();
  notes.push_back("one judged flight (" + pool.judged.flights.front()->name +
                  "): the top level is that flight's own verdict, held out within the flight");
  analysis.notes.insert(analysis.notes.end(), notes.begin(), notes.end());
  session.single_flight = true;
}

// Baseline and where, pooled over every flight's nominal fit.
void describe_pooled_baseline(Analysis& analysis, const PooledData& pool, const EffectFit& none_all,
                              const NominalInertia& nominal) {
  BaselineGap baseline;
  std::vector<Vec3> readings;
  for (std::size_t f = 0; f < pool.judged.flights.size(); ++f) {
    predict(none_all, nominal, f, *pool.judged.flights[f], readings);
    baseline.add(*pool.judged.flights[f], readings, pool.judged.inverse_sigma[f]);
  }
  baseline.describe(analysis);
}

}  // namespace

SessionDiagnosis diagnose_session(std::vector<Flight>& flights, const NominalInertia& nominal, int threads,
                                  const ParallelProgress& flights_done) {
  SessionDiagnosis session;
  session.flights.resize(flights.size());
  const unsigned workers = static_cast<unsigned>(std::max(threads, 1));
  parallel_for(
      flights.size(), workers,
      [&](std::size_t i) { session.flights[i] = diagnose_flight(flights[i], nominal); }, flights_done);

  PooledData pool = pool_judged_flights(session, flights);
  Analysis& analysis = session.pooled;
  const std::size_t count = pool.judged.flights.size();
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
  // The coarsest resolution of the pooled flights (those left out have none).
  double resolution = 0.0;
  for (const FlightDiagnosis& d : session.flights) resolution = std::max(resolution, d.noise.resolution);
  RankingContext context = pool.judged.ranking_context(nominal, resolution);
  context.own_analyses = pool.own;
  judge_candidates(analysis, context, FlightsLeftOut(pool.judged, pool.own, nominal, none_all, workers));
  set_spin_up_end(analysis, pool.judged.flights);
  note_disagreeing_flights(analysis, pool.judged.flights, pool.own);
  note_between_flight_scatter(analysis, pool.own, pool.judged.flights);
  add_flip_periods(session, pool, none_all, flights, nominal);
  // Onsets relative to each flight's start: the flights' clocks need not be one.
  std::vector<double> onsets;
  for (const FlightDiagnosis& d : session.flights) {
    if (d.analysis.where.onset_s) onsets.push_back(*d.analysis.where.onset_s - d.start_s);
  }
  set_median_onset(analysis, std::move(onsets));
  return session;
}

}  // namespace aloft::host::diagnose
