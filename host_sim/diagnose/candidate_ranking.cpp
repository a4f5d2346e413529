#include "diagnose/candidate_ranking.hpp"

#include <algorithm>
#include <cmath>

#include "aloft/deviation.hpp"

namespace aloft::host::diagnose {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

// The standard error below which a parameter counts as informed by the flight, in the
// units of theta (flight_model.hpp): what a useful diagnosis must resolve.
double tolerance(Effect effect, double mean_speed, double duration_s) {
  switch (effect) {
    case Effect::inertia_moments: return 0.03;     // 3 % of a moment ratio
    case Effect::inertia_axes:
    case Effect::sensor_misalignment: return 1.0 / kDeg;  // 1 degree
    case Effect::aero_torque:  // a drag that changes |w| by 1 % over the flight
      return 0.01 / std::max(mean_speed * duration_s, 1e-6);
    case Effect::internal_damping: return 2.0;     // log scales of rotor size and rate
    case Effect::impulse: return 0.05;             // rad/s of jump
    case Effect::gyro_bias: return 0.01;           // rad/s
    case Effect::gyro_scale: return 0.005;
    case Effect::clock_drift: return 0.005;
    case Effect::none: return 1.0;
  }
  return 1.0;
}

// With 3 % slack: a fitted tensor of a flat body sits on the boundary and noise may push it
// just across; a measured nominal (the racquet) may start 2 % beyond it.
bool triangle_holds(const Eigen::Vector3d& m) {
  const double slack = 0.03 * m.sum();
  return m(0) <= m(1) + m(2) + slack && m(1) <= m(0) + m(2) + slack && m(2) <= m(0) + m(1) + slack;
}

// Root mean square difference of two candidates' held-out predictions, in noise units.
double prediction_distance(const Candidate& a, const Candidate& b,
                           const std::vector<const Flight*>& flights,
                           const std::vector<Eigen::Vector3d>& inverse_sigma) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t f = 0; f < flights.size(); ++f) {
    if (f >= a.heldout_readings.size() || f >= b.heldout_readings.size()) continue;
    const auto& pa = a.heldout_readings[f];
    const auto& pb = b.heldout_readings[f];
    for (std::size_t k = 0; k < pa.size() && k < pb.size(); ++k) {
      if (!flights[f]->usable[k]) continue;
      sum += (pa[k] - pb[k]).cwiseProduct(inverse_sigma[f]).squaredNorm();
      count += 3;
    }
  }
  return count > 0 ? std::sqrt(sum / count) : 1e300;
}

}  // namespace

void GapSums::add(const Eigen::Vector3d& predicted, const Eigen::Vector3d& measured,
                  const Eigen::Vector3d& inverse_sigma) {
  chi_square += (predicted - measured).cwiseProduct(inverse_sigma).squaredNorm();
  residuals += 3;
  if (measured.squaredNorm() > 0.0) {
    const double da = deviation_angle<double>(predicted, measured);
    const double rel = relative_error<double>(predicted, measured);
    da_sq += da * da;
    rel_sq += rel * rel;
    ++samples;
  }
}

double GapSums::rms_da_deg() const { return samples ? std::sqrt(da_sq / samples) * kDeg : 0.0; }
double GapSums::rms_rel_err() const { return samples ? std::sqrt(rel_sq / samples) : 0.0; }

void rank_candidates(Analysis& analysis, bool gyro_input, const std::vector<const Flight*>& flights,
                     const std::vector<Eigen::Vector3d>& inverse_sigma, double mean_speed,
                     double duration_s) {
  std::vector<Candidate>& all = analysis.candidates;
  const auto none_it = std::find_if(all.begin(), all.end(),
                                    [](const Candidate& c) { return c.effect == Effect::none; });
  const Candidate none = none_it != all.end() ? *none_it : Candidate{};
  // Overdispersion: when even the best candidate leaves a held-out gap far beyond the
  // noise floor (real data: the models are approximations and the phone's noise is not
  // white), chi-square differences overstate the evidence by that factor. Dividing by the
  // best reduced chi-square keeps the penalty and the margin meaningful (quasi-likelihood).
  double dispersion = 1e300;
  for (const Candidate& c : all) {
    if (c.evaluated && c.heldout_residuals > 0) {
      dispersion = std::min(dispersion, c.heldout_chi_square / c.heldout_residuals);
    }
  }
  dispersion = std::max(1.0, dispersion < 1e299 ? dispersion : 1.0);
  analysis.dispersion = dispersion;
  for (Candidate& c : all) {
    if (!c.evaluated) {
      c.score = 1e300;
      continue;
    }
    c.score = c.heldout_chi_square / dispersion + kPenaltyPerParameter * effect_penalty_count(c.effect);
    c.shrink = none.heldout_rms_rel_err > 0 ? 1.0 - c.heldout_rms_rel_err / none.heldout_rms_rel_err : 0.0;
    c.shrink_da = none.heldout_rms_da_deg > 0 ? 1.0 - c.heldout_rms_da_deg / none.heldout_rms_da_deg : 0.0;
    // Identifiable: every parameter is pinned to within the tolerance. A rotation about a
    // symmetry axis of the body is no parameter at all (it changes nothing), so for the
    // two rotation effects uninformed directions are skipped; for every other effect an
    // uninformed parameter (e.g. a common scale of the two transverse axes of a symmetric
    // body, which trades against the initial rate) makes the effect not identifiable.
    const double tol = tolerance(c.effect, mean_speed, duration_s);
    const bool gauge = c.effect == Effect::inertia_axes || c.effect == Effect::sensor_misalignment;
    bool informed = c.fit.theta_standard_error.size() == 0;
    c.identifiable = true;
    for (Eigen::Index i = 0; i < c.fit.theta_standard_error.size(); ++i) {
      const double se = c.fit.theta_standard_error(i);
      if (!std::isfinite(se) && gauge) continue;
      informed = informed || std::isfinite(se);
      if (!(se <= tol)) c.identifiable = false;
    }
    if (!informed) c.identifiable = false;
    if (!c.identifiable && c.note.empty()) {
      c.note = "not identifiable: this flight (too short, too slow, or a symmetric body) does not "
               "pin its parameters";
    }
    if (c.effect == Effect::aero_torque && c.fit.theta.size() == 1) {
      const double se = c.fit.theta_standard_error(0);
      if (c.fit.theta(0) < -3.0 * (std::isfinite(se) ? se : 0.0) && c.fit.theta(0) < 0) {
        c.physical = false;
        c.note = "unphysical: negative drag (energy gain)";
      }
    }
    if (c.effect == Effect::inertia_moments && !triangle_holds(c.params.principal_kg_m2)) {
      c.physical = false;
      c.note = "unphysical: fitted moments break the triangle inequality";
    }
  }
  std::stable_sort(all.begin(), all.end(),
                   [](const Candidate& a, const Candidate& b) { return a.score < b.score; });

  Verdict& v = analysis.verdict;
  const Candidate* none_ptr = nullptr;
  const Candidate* best = nullptr;
  for (const Candidate& c : all) {
    if (c.effect == Effect::none) none_ptr = &c;
    if (best == nullptr && c.evaluated && c.physical && c.effect != Effect::none) best = &c;
  }
  const bool beats_noise = none_ptr != nullptr && best != nullptr &&
                           best->score < none_ptr->score - kVerdictMargin;
  const Candidate* chosen = beats_noise ? best : none_ptr;
  v.chosen = chosen != nullptr ? static_cast<int>(chosen - all.data()) : -1;
  v.effect = chosen != nullptr ? chosen->effect : Effect::none;
  v.equivalent = always_equivalent(v.effect, gyro_input);
  if (none_ptr != nullptr) {
    v.heldout_rms_da_before_deg = none_ptr->heldout_rms_da_deg;
    v.heldout_rms_rel_err_before = none_ptr->heldout_rms_rel_err;
  }
  if (chosen != nullptr) {
    v.heldout_rms_da_after_deg = chosen->heldout_rms_da_deg;
    v.heldout_rms_rel_err_after = chosen->heldout_rms_rel_err;
  }
  // Effects the data cannot tell apart from the chosen one here: they explain the gap as
  // well (score within the margin) with practically the same predictions (< 0.3 sigma).
  if (beats_noise) {
    for (Candidate& c : all) {
      if (&c == chosen || !c.evaluated || c.effect == Effect::none) continue;
      if (c.score < chosen->score + kVerdictMargin &&
          prediction_distance(c, *chosen, flights, inverse_sigma) < 0.3 * std::sqrt(dispersion)) {
        if (std::find(v.equivalent.begin(), v.equivalent.end(), c.effect) == v.equivalent.end()) {
          v.equivalent.push_back(c.effect);
        }
      }
    }
    for (Candidate& c : all) {
      if (std::find(v.equivalent.begin(), v.equivalent.end(), c.effect) != v.equivalent.end()) {
        for (Effect e : v.equivalent) {
          if (e != c.effect) c.indistinguishable.push_back(e);
        }
      }
    }
    if (!chosen->identifiable) {
      v.confident = false;
      v.could_not_judge.push_back(std::string(effect_name(chosen->effect)) +
                                  " explains the gap but its parameters are poorly determined");
    }
  }
}

}  // namespace aloft::host::diagnose
