// The pooled analysis of a session (SPEC §4 with --segments): every effect except the
// impulse (a knock belongs to one flight) is shared by all flights, each flight keeping
// its own initial rate. Held out: leave one flight out. The effect is fitted to the other
// flights (one Gauss-Newton step from the all-flights solution, effect_fit.hpp); on the
// left-out flight only the initial rate is fitted, on one fold of its samples, and the gap
// is judged on the other fold (and the other way round), so that no sample is ever judged
// by a fit that saw it.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "common/parallel_for.hpp"
#include "diagnose/candidate_ranking.hpp"
#include "diagnose/diagnosis.hpp"
#include "diagnose/held_out.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;

struct PooledData {
  std::vector<const Flight*> flights;
  std::vector<Vec3> inverse_sigma;
  std::vector<FlightData> all;                  // every sample of every flight
  std::vector<std::array<FlightData, 2>> train;  // fold training masks per flight
  std::vector<Folds> folds;
};

bool mentions_intermediate(const std::string& comment) {
  std::string lower = comment;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower.find("intermediate") != std::string::npos;
}

// Flip periods per flight, nominal and with the pooled verdict's effect (parameters
// fitted without that flight), and their mean errors.
void add_flip_periods(SessionDiagnosis& session, const std::vector<const Flight*>& pooled,
                      const std::vector<Flight>& flights, const NominalInertia& nominal) {
  const Analysis& a = session.pooled;
  const Candidate* chosen = a.verdict.chosen >= 0 && a.verdict.effect != Effect::none
                                ? &a.candidates[static_cast<std::size_t>(a.verdict.chosen)]
                                : nullptr;
  const EffectModel model{a.verdict.effect, nominal, 0.0};
  for (std::size_t i = 0; i < flights.size(); ++i) {
    const auto it = std::find(pooled.begin(), pooled.end(), &flights[i]);
    if (it == pooled.end()) continue;
    const std::size_t j = static_cast<std::size_t>(it - pooled.begin());
    const bool with_effect = chosen != nullptr && j < chosen->heldout_theta.size();
    session.flights[i].flip_period = flip_period(flights[i], nominal, with_effect ? &model : nullptr,
                                                 with_effect ? chosen->heldout_theta[j] : Eigen::VectorXd());
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
      summary.mean_error_diagnosed += std::abs(*fp->diagnosed_s - fp->measured_s) / fp->measured_s;
    }
  }
  if (summary.flights == 0) return;
  summary.mean_error_nominal /= summary.flights;
  if (summary.diagnosed_flights > 0) summary.mean_error_diagnosed /= summary.diagnosed_flights;
  session.flip_period = summary;
}

}  // namespace

SessionDiagnosis diagnose_session(const std::vector<Flight>& flights, const NominalInertia& nominal,
                                  int threads) {
  SessionDiagnosis session;
  session.flights.resize(flights.size());
  const unsigned workers = static_cast<unsigned>(std::max(threads, 1));
  parallel_for(flights.size(), workers,
               [&](std::size_t i) { session.flights[i] = diagnose_flight(flights[i], nominal); });

  // Only flights that could be judged on their own take part in the pooled analysis.
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
    const Vec3 inv = d.noise.sigma.cwiseInverse();
    pool.flights.push_back(&flights[i]);
    pool.inverse_sigma.push_back(inv);
    pool.all.push_back(FlightData{&flights[i], all_samples(flights[i].size()), inv});
    pool.folds.push_back(interleaved_folds(flights[i].size()));
    pool.train.push_back({FlightData{&flights[i], pool.folds.back().train[0], inv},
                          FlightData{&flights[i], pool.folds.back().train[1], inv}});
  }
  Analysis& analysis = session.pooled;
  const std::size_t count = pool.flights.size();
  if (count < 2) {
    analysis.verdict.confident = false;
    analysis.verdict.could_not_judge.push_back(
        "fewer than two judged flights: nothing to leave out for a pooled analysis");
    return session;
  }

  const EffectFit none_all = fit_effect(Effect::none, nominal, pool.all, nullptr);
  // Baseline and where, pooled over every flight's nominal fit.
  {
    GapSums sums;
    Vec3 body_sq = Vec3::Zero();
    int body_count = 0;
    std::vector<Vec3> readings;
    for (std::size_t f = 0; f < count; ++f) {
      const Flight& flight = *pool.flights[f];
      predict(none_all, nominal, f, flight, readings);
      const Eigen::Matrix3d to_body = flight.sensor_to_body.toRotationMatrix();
      for (std::size_t k = 0; k < flight.size(); ++k) {
        if (!flight.usable[k]) continue;
        sums.add(readings[k], flight.omega[k], pool.inverse_sigma[f]);
        body_sq += (to_body * (readings[k] - flight.omega[k])).cwiseAbs2();
        ++body_count;
      }
    }
    analysis.baseline.rms_da_deg = sums.rms_da_deg();
    analysis.baseline.rms_rel_err = sums.rms_rel_err();
    analysis.where.rms_gap_body_rad_s = (body_sq / std::max(body_count, 1)).cwiseSqrt();
    Eigen::Index axis = 0;
    analysis.where.rms_gap_body_rad_s.maxCoeff(&axis);
    analysis.where.dominant_axis = axis == 0 ? "x" : (axis == 1 ? "y" : "z");
    analysis.where.gap_over_noise = sums.residuals ? sums.chi_square / sums.residuals : 0.0;
  }

  double speed_sum = 0.0, duration_sum = 0.0;
  for (const Flight* f : pool.flights) {
    double s = 0;
    for (const auto& w : f->omega) s += w.norm();
    speed_sum += s / std::max<std::size_t>(f->size(), 1);
    duration_sum += f->end_s() - f->start_s();
  }
  // The pooled fit informs shared parameters with every flight's data.
  const double mean_speed = speed_sum / count;
  const double total_duration = duration_sum;

  for (Effect effect : candidate_effects(pool.flights.front()->gyro_input)) {
    Candidate c;
    c.effect = effect;
    if (effect == Effect::impulse) {
      c.evaluated = false;
      c.note = "per flight only: an impulse is not shared by the flights of a session";
      analysis.candidates.push_back(std::move(c));
      continue;
    }
    c.fit = effect == Effect::none ? none_all : fit_effect(effect, nominal, pool.all, &none_all);
    EffectModel model{effect, nominal, 0.0};
    c.params = effect_parameters(model, c.fit.theta);
    c.heldout_readings.assign(count, {});
    std::vector<GapSums> sums(count);
    const std::vector<Eigen::VectorXd> left_out =
        effect == Effect::none ? std::vector<Eigen::VectorXd>(count, c.fit.theta)
                               : leave_one_flight_out(c.fit, nominal, pool.all);
    c.heldout_theta = left_out;
    parallel_for(count, workers, [&](std::size_t j) {
      // The effect from every flight but j, then flight j's initial rate on one fold of
      // its samples, judged on the other.
      EffectFit others = c.fit;
      others.theta = left_out[j];
      const Flight& flight = *pool.flights[j];
      std::vector<Vec3> heldout(flight.size(), Vec3::Zero());
      std::vector<Vec3> readings;
      for (int f = 0; f < 2; ++f) {
        EffectFit none_j;
        none_j.effect = Effect::none;
        none_j.theta = Eigen::VectorXd();
        none_j.flights = {none_all.flights[j]};
        const EffectFit rates = fit_initial_rates(others, nominal, {pool.train[j][static_cast<std::size_t>(f)]}, &none_j);
        predict(rates, nominal, 0, flight, readings);
        for (std::size_t k = 0; k < flight.size(); ++k) {
          if (!pool.folds[j].judge[static_cast<std::size_t>(f)][k]) continue;
          heldout[k] = readings[k];
          if (flight.usable[k]) sums[j].add(readings[k], flight.omega[k], pool.inverse_sigma[j]);
        }
      }
      c.heldout_readings[j] = std::move(heldout);
    });
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
    analysis.candidates.push_back(std::move(c));
  }
  rank_candidates(analysis, pool.flights.front()->gyro_input, pool.flights, pool.inverse_sigma,
                  mean_speed, total_duration);
  add_flip_periods(session, pool.flights, flights, nominal);
  // Onset of a session: the median of the flights' onsets, relative to each flight's start.
  std::vector<double> onsets;
  for (const FlightDiagnosis& d : session.flights) {
    if (d.analysis.where.onset_s) onsets.push_back(*d.analysis.where.onset_s - d.start_s);
  }
  if (analysis.verdict.effect != Effect::none && !onsets.empty()) {
    std::nth_element(onsets.begin(), onsets.begin() + static_cast<std::ptrdiff_t>(onsets.size() / 2), onsets.end());
    analysis.where.onset_s = onsets[onsets.size() / 2];
    analysis.notes.push_back("pooled where.onset_s is the median over flights, seconds after each flight's start");
  }
  return session;
}

}  // namespace aloft::host::diagnose
