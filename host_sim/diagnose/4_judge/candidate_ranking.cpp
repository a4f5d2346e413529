#include "diagnose/4_judge/candidate_ranking.hpp"

#include "diagnose/4_judge/confidence.hpp"

#include <algorithm>
#include <cmath>

#include "aloft/deviation.hpp"
#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/4_judge/moment_scale_equivalence.hpp"

namespace aloft::host::diagnose {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

// Root mean square difference of two candidates' held-out predictions, in noise units.
double prediction_distance(const Candidate& a, const Candidate& b, const std::vector<const Flight*>& flights,
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

namespace {

// Identifiable: every parameter is pinned to within its effect's tolerance. A rotation
// about a symmetry axis of the body is no parameter at all (it changes nothing), so for the
// two rotation effects uninformed directions are skipped; for every other effect an
// uninformed parameter (e.g. a common scale of the two transverse axes of a symmetric
// body, which trades against the initial rate) makes the effect not identifiable.
bool identifiable(const Candidate& c, double mean_speed, double duration_s) {
  const Eigen::VectorXd& se = c.fit.theta_standard_error;
  if (se.size() == 0) return false;
  std::vector<Effect> effects = c.base;
  effects.push_back(c.effect);
  Eigen::Index offset = 0;
  bool informed = false;
  for (Effect e : effects) {
    const double tol = describe(e).hooks.tolerance(mean_speed, duration_s);
    const bool gauge = describe(e).rotation_gauge;
    for (int i = 0; i < effect_parameter_count(e) && offset < se.size(); ++i, ++offset) {
      if (!std::isfinite(se(offset)) && gauge) continue;
      informed = informed || std::isfinite(se(offset));
      if (!(se(offset) <= tol)) return false;
    }
  }
  return informed;
}

// The slice of a fitted vector that belongs to an effect at `offset` (empty when the fit
// holds fewer values).
Eigen::VectorXd slice(const Eigen::VectorXd& v, int offset, int count) {
  if (offset < 0 || offset + count > v.size()) return Eigen::VectorXd();
  return v.segment(offset, count);
}

// Each effect of the model judges its own fit (descriptor `unphysical`), those the model
// started from first; the last objection is the note.
void judge_physics(Candidate& c) {
  const EffectModel model(c.effect, NominalInertia(), 0.0, c.base);
  for (Effect e : model_effects(model)) {
    const int offset = theta_offset(model, e);
    const int count = effect_parameter_count(e);
    const FittedSlice fit{slice(c.fit.theta, offset, count), slice(c.fit.theta_standard_error, offset, count),
                          e == c.effect ? &c.params : nullptr};
    const std::string why = describe(e).hooks.unphysical(fit);
    if (!why.empty()) {
      c.physical = false;
      c.note = why;
    }
  }
}

// A gyro scale can stand in for wrong moments, never the reverse (moment_scale_equivalence.hpp):
// listed with a moments verdict only where the gyro reads the principal axes and a scale
// reproduces the fitted moments exactly; never listed with a scale verdict.
bool one_way_equivalence_allows(const Candidate& best, const Candidate& other,
                                const RankingContext& context) {
  if (best.effect == Effect::gyro_scale && other.effect == Effect::inertia_moments) return false;
  if (best.effect != Effect::inertia_moments || other.effect != Effect::gyro_scale) return true;
  if (context.nominal == nullptr || context.flights.empty()) return false;
  return gyro_along_principal_axes(context.nominal->principal_axes,
                                   context.flights.front()->sensor_to_body) &&
         scale_mimicking_moments(context.nominal->principal_moments, best.params.principal_kg_m2).has_value();
}

}  // namespace

StepRanking rank_step(std::vector<Candidate>& all, const RankingContext& context, double margin) {
  StepRanking out;
  const auto ref_it = std::find_if(all.begin(), all.end(), [](const Candidate& c) { return c.reference; });
  const Candidate reference = ref_it != all.end() ? *ref_it : Candidate{};
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
  out.dispersion = dispersion;
  for (Candidate& c : all) {
    if (!c.evaluated) {
      c.score = 1e300;
      continue;
    }
    int parameters = 0;
    for (Effect e : c.base) parameters += effect_penalty_count(e);
    if (!c.reference || c.effect != Effect::none) parameters += effect_penalty_count(c.effect);
    c.score = c.heldout_chi_square / dispersion + kPenaltyPerParameter * parameters;
    c.shrink =
        reference.heldout_rms_rel_err > 0 ? 1.0 - c.heldout_rms_rel_err / reference.heldout_rms_rel_err : 0.0;
    c.reference_rms_rel_err = reference.heldout_rms_rel_err;
    c.shrink_da =
        reference.heldout_rms_da_deg > 0 ? 1.0 - c.heldout_rms_da_deg / reference.heldout_rms_da_deg : 0.0;
    if (c.reference) continue;
    c.identifiable = identifiable(c, context.mean_speed, context.duration_s);
    if (!c.identifiable && c.note.empty()) {
      c.note =
          "not identifiable: this flight (too short, too slow, or a symmetric body) does not "
          "pin its parameters";
    }
    judge_physics(c);
  }
  std::stable_sort(all.begin(), all.end(),
                   [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Candidate& c = all[i];
    if (c.reference) out.reference = static_cast<int>(i);
    if (out.best < 0 && c.evaluated && c.physical && !c.reference && c.effect != Effect::none) {
      out.best = static_cast<int>(i);
    }
  }
  if (out.best < 0 || out.reference < 0) return out;
  const Candidate& best = all[static_cast<std::size_t>(out.best)];
  out.beats_reference = best.score < all[static_cast<std::size_t>(out.reference)].score - margin;
  out.equivalent = always_equivalent(best.effect, context.gyro_input);
  // Effects the data cannot tell apart from the best one here: they explain the gap as
  // well (score within the margin) with practically the same predictions (< 0.3 sigma).
  for (const Candidate& c : all) {
    if (&c == &best || !c.evaluated || c.reference || c.effect == Effect::none) continue;
    if (c.score < best.score + margin && one_way_equivalence_allows(best, c, context) &&
        prediction_distance(c, best, context.flights, context.inverse_sigma) < 0.3 * std::sqrt(dispersion)) {
      if (std::find(out.equivalent.begin(), out.equivalent.end(), c.effect) == out.equivalent.end()) {
        out.equivalent.push_back(c.effect);
      }
    }
  }
  if (out.beats_reference) {
    for (Candidate& c : all) {
      if (std::find(out.equivalent.begin(), out.equivalent.end(), c.effect) == out.equivalent.end()) continue;
      for (Effect e : out.equivalent) {
        if (e != c.effect) c.indistinguishable.push_back(e);
      }
    }
  }
  return out;
}

void rank_candidates(Analysis& analysis, bool gyro_input, const std::vector<const Flight*>& flights,
                     const std::vector<Eigen::Vector3d>& inverse_sigma, double mean_speed,
                     double duration_s) {
  rank_candidates(analysis, RankingContext{gyro_input, flights, inverse_sigma, mean_speed, duration_s});
}

void rank_candidates(Analysis& analysis, const RankingContext& context) {
  const bool gyro_input = context.gyro_input;
  std::vector<Candidate>& all = analysis.candidates;
  for (Candidate& c : all) c.reference = c.effect == Effect::none && c.base.empty();
  const StepRanking step = rank_step(all, context, kVerdictMargin);
  analysis.dispersion = step.dispersion;
  Verdict& v = analysis.verdict;
  const Candidate* none_ptr = step.reference >= 0 ? &all[static_cast<std::size_t>(step.reference)] : nullptr;
  const Candidate* chosen = step.beats_reference ? &all[static_cast<std::size_t>(step.best)] : none_ptr;
  v.chosen = chosen != nullptr ? static_cast<int>(chosen - all.data()) : -1;
  v.effect = chosen != nullptr ? chosen->effect : Effect::none;
  v.equivalent = step.beats_reference ? step.equivalent : always_equivalent(Effect::none, gyro_input);
  if (none_ptr != nullptr) {
    v.heldout_rms_da_before_deg = none_ptr->heldout_rms_da_deg;
    v.heldout_rms_rel_err_before = none_ptr->heldout_rms_rel_err;
  }
  if (chosen != nullptr) {
    v.heldout_rms_da_after_deg = chosen->heldout_rms_da_deg;
    v.heldout_rms_rel_err_after = chosen->heldout_rms_rel_err;
  }
  if (step.beats_reference && !chosen->identifiable) {
    v.confident = false;
    v.could_not_judge.push_back(std::string(effect_name(chosen->effect)) +
                                " explains the gap but its parameters are poorly determined");
  }
}

}  // namespace aloft::host::diagnose
