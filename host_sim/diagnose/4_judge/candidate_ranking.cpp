#include "diagnose/4_judge/candidate_ranking.hpp"

#include "diagnose/4_judge/confidence.hpp"

#include <algorithm>
#include <cmath>

#include "aloft/dynamics/deviation.hpp"
#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/4_judge/score_spread.hpp"
#include "diagnose/4_judge/told_apart.hpp"

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
    const EffectDescriptor& d = describe(e);
    const double tol = d.hooks.tolerance(mean_speed, duration_s);
    const Eigen::Index count = std::min<Eigen::Index>(effect_parameter_count(e), se.size() - offset);
    Eigen::VectorXd errors = se.segment(offset, count);
    if (d.pinned_errors != nullptr && count == effect_parameter_count(e) &&
        offset + count <= c.fit.theta.size())
      errors = d.pinned_errors(c.fit.theta.segment(offset, count), errors);
    offset += count;
    for (Eigen::Index i = 0; i < count; ++i) {
      if (!std::isfinite(errors(i)) && d.rotation_gauge) continue;
      informed = informed || std::isfinite(errors(i));
      if (!(errors(i) <= tol)) return false;
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

// An effect that stands in for another one way (descriptor `one_way_equivalent`: a gyro
// scale for wrong moments) is listed with a verdict of the other only where the condition
// holds for that verdict's fit, and the other is never listed with a verdict of it.
bool one_way_equivalence_allows(const Candidate& best, const Candidate& other,
                                const RankingContext& context) {
  if (describe(best.effect).one_way_equivalent.stands_in_for == other.effect) return false;
  const OneWayEquivalence& stand_in = describe(other.effect).one_way_equivalent;
  if (stand_in.stands_in_for != best.effect) return true;
  if (context.nominal == nullptr || context.flights.empty()) return false;
  return stand_in.holds(best.params, *context.nominal, context.flights.front()->sensor_to_body);
}

bool eligible(const Candidate& c) {
  return c.evaluated && c.physical && !c.reference && c.effect != Effect::none;
}

bool contains(const std::vector<Effect>& list, Effect e) {
  return std::find(list.begin(), list.end(), e) != list.end();
}

// Overdispersion: when even the best candidate leaves a held-out gap far beyond the
// noise floor (real data: the models are approximations and the phone's noise is not
// white), chi-square differences overstate the evidence by that factor. Dividing by the
// best reduced chi-square keeps the penalty and the margin meaningful (quasi-likelihood).
double dispersion_of(const std::vector<Candidate>& all) {
  double dispersion = 1e300;
  for (const Candidate& c : all) {
    if (c.evaluated && c.heldout_residuals > 0) {
      dispersion = std::min(dispersion, c.heldout_chi_square / c.heldout_residuals);
    }
  }
  return std::max(1.0, dispersion < 1e299 ? dispersion : 1.0);
}

// The other minima of c's search that fit about as well as the one it kept, and better
// than the step's reference by more than that (else both are the reference's fit, e.g. a
// rotor too small or too loose to act, whose parameters wander without changing a thing).
std::vector<Candidate::Alternative> close_minima(const Candidate& c, const Candidate& reference,
                                                 const RankingContext& context) {
  std::vector<Candidate::Alternative> out;
  const int parameters = static_cast<int>(c.fit.theta.size() + 3 * c.fit.flights.size());
  const double dispersion = std::max(1.0, c.fit.cost / std::max(1, c.fit.residual_count - parameters));
  for (const OtherMinimum& m : c.fit.other_minima) {
    const double behind = (m.cost - c.fit.cost) / dispersion;
    const bool acts = (reference.fit.cost - m.cost) / dispersion > kCloseMinimum;
    if (behind > kCloseMinimum || !acts || std::abs(behind) < kSameMinimum) continue;
    Candidate::Alternative a;
    a.cost_behind = behind;
    if (context.nominal != nullptr && !c.fit.flights.empty()) {
      EffectModel model = model_of(c.fit, *context.nominal, 0);
      model.impulse_time_s = m.impulse_time_s;
      a.params = effect_parameters(model, m.theta, c.effect);
    }
    out.push_back(a);
  }
  return out;
}

// Scores every candidate against `reference` and judges its parameters and physics.
void score_candidates(std::vector<Candidate>& all, const Candidate& reference, const RankingContext& context,
                      double dispersion) {
  for (Candidate& c : all) {
    if (!c.evaluated) {
      c.score = 1e300;
      continue;
    }
    c.score = c.heldout_chi_square / dispersion + kPenaltyPerParameter * penalty_count(c);
    c.shrink =
        reference.heldout_rms_rel_err > 0 ? 1.0 - c.heldout_rms_rel_err / reference.heldout_rms_rel_err : 0.0;
    c.reference_rms_rel_err = reference.heldout_rms_rel_err;
    c.shrink_da =
        reference.heldout_rms_da_deg > 0 ? 1.0 - c.heldout_rms_da_deg / reference.heldout_rms_da_deg : 0.0;
    if (c.reference) continue;
    c.alternatives = close_minima(c, reference, context);
    c.identifiable = identifiable(c, context.mean_speed, context.duration_s);
    if (!c.identifiable && c.note.empty()) {
      c.note =
          "not identifiable: this flight (too short, too slow, or a symmetric body) does not "
          "pin its parameters";
    }
    judge_physics(c);
    if (describe(c.effect).named_only_when_told_apart && !context.own_analyses.empty()) {
      const std::string why = flights_disagree_on(c, context.own_analyses);
      if (!why.empty()) {
        c.physical = false;
        c.note = why;
      }
    }
  }
}

// The effects the data cannot tell apart from `head`: its class that always holds, and
// those that explain the gap as well (score within the margin) with practically the same
// predictions (< 0.3 sigma). `head` first, the rest in the registry's order.
std::vector<Effect> class_of(const std::vector<Candidate>& all, const Candidate& head,
                             const RankingContext& context, double margin, double dispersion) {
  std::vector<Effect> out = always_equivalent(head.effect, context.gyro_input);
  for (const Candidate& c : all) {
    if (&c == &head || !c.evaluated || c.reference || c.effect == Effect::none) continue;
    if (c.score < head.score + margin && one_way_equivalence_allows(head, c, context) &&
        prediction_distance(c, head, context.flights, context.inverse_sigma) < 0.3 * std::sqrt(dispersion)) {
      if (!contains(out, c.effect)) out.push_back(c.effect);
    }
  }
  std::sort(out.begin() + 1, out.end());
  return out;
}

// Every candidate's spread, and its score behind `head` with the spread of that difference.
void measure_against(std::vector<Candidate>& all, std::size_t head,
                     const std::vector<std::vector<double>>& chunks, double dispersion) {
  for (std::size_t i = 0; i < all.size(); ++i) {
    Candidate& c = all[i];
    if (!c.evaluated) continue;
    c.score_spread = spread_of_sum(chunks[i]) / dispersion;
    c.score_behind = c.score - all[head].score;
    c.score_behind_spread = spread_of_difference(chunks[i], chunks[head]) / dispersion;
  }
}

// Who heads a tie (confidence.hpp): of the effects one with best both ways
// (always_equivalent, e.g. inertia_axes and sensor_misalignment from a gyro) that tie with
// it, and of any candidate within the rounding tolerance, the first in the registry.
// Not the classes the data finds (score within the margin, close predictions): on the
// withheld flights those hold wrong moments beside a misalignment, and the registry's
// order named the moments there. Nor a class that holds one way only (a clock drift is a
// uniform gyro scale, not the reverse): the registry would name the general model where
// its special case fits as well (imu_clock_drift_2). Needs measure_against(best).
std::size_t fixed_order_headline(const std::vector<Candidate>& all, std::size_t best, bool gyro_input) {
  const std::vector<Effect> best_class = always_equivalent(all[best].effect, gyro_input);
  std::size_t head = best;
  for (std::size_t i = 0; i < all.size(); ++i) {
    const Candidate& c = all[i];
    if (!eligible(c)) continue;
    const bool one =
        contains(best_class, c.effect) && contains(always_equivalent(c.effect, gyro_input), all[best].effect);
    const bool tie = one ? scores_tie(c.score_behind, c.score_behind_spread)
                         : std::abs(c.score_behind) <= kScoreRoundingTolerance;
    if (tie && c.effect < all[head].effect) head = i;
  }
  return head;
}

// Members of one class both ways (always_equivalent) whose scores lie within the rounding
// tolerance of each other are listed in the registry's order, as fixed_order_headline
// names them: which of them a fit left a bit lower is the last bits of its path, not the
// data (practice3 T06's second step: inertia_axes and sensor_misalignment, 3307.7514 both,
// swapped places when the fold refits changed their start). Keeps `out`'s indices on
// their candidates.
void list_ties_in_registry_order(std::vector<Candidate>& all, StepRanking& out, bool gyro_input) {
  const auto swaps = [&](const Candidate& a, const Candidate& b) {
    return b.effect < a.effect && a.base == b.base &&
           std::abs(a.score - b.score) <= kScoreRoundingTolerance &&
           contains(always_equivalent(a.effect, gyro_input), b.effect) &&
           contains(always_equivalent(b.effect, gyro_input), a.effect);
  };
  for (bool swapped = true; swapped;) {
    swapped = false;
    for (std::size_t i = 0; i + 1 < all.size(); ++i) {
      if (!swaps(all[i], all[i + 1])) continue;
      std::swap(all[i], all[i + 1]);
      for (int* index : {&out.best, &out.reference}) {
        if (*index == static_cast<int>(i))
          *index = static_cast<int>(i + 1);
        else if (*index == static_cast<int>(i + 1))
          *index = static_cast<int>(i);
      }
      swapped = true;
    }
  }
}

// The best eligible candidate of an effect other than all[head]'s, or -1.
int best_other(const std::vector<Candidate>& all, std::size_t head) {
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (eligible(all[i]) && all[i].effect != all[head].effect) return static_cast<int>(i);
  }
  return -1;
}

// all[best], or the candidate that heads in its place when all[best] is an effect named
// only when told apart and is not (told_apart.hpp; -1: none does). `listed`: all[best]
// when it is to be listed as indistinguishable from the one in its place, else -1.
// Needs measure_against(best).
int told_apart_best(std::vector<Candidate>& all, std::size_t best, const RankingContext& context,
                    int& listed) {
  listed = -1;
  if (!describe(all[best].effect).named_only_when_told_apart) return static_cast<int>(best);
  const int rival = best_other(all, best);
  const NotToldApart not_told = told_apart(
      all[best], rival >= 0 ? &all[static_cast<std::size_t>(rival)] : nullptr, context.own_analyses.empty());
  if (not_told.why.empty()) return static_cast<int>(best);
  all[best].note = not_told.why;
  if (not_told.indistinguishable) listed = static_cast<int>(best);
  return rival;
}

// The class's members name each other; a tie outside the class and the headline name
// each other.
void mark_indistinguishable(std::vector<Candidate>& all, const StepRanking& out) {
  Candidate& head = all[static_cast<std::size_t>(out.best)];
  for (Candidate& c : all) {
    if (contains(out.equivalent, c.effect)) {
      for (Effect e : out.equivalent) {
        if (e != c.effect) c.indistinguishable.push_back(e);
      }
    } else if (contains(out.tied, c.effect)) {
      c.indistinguishable.push_back(head.effect);
    }
  }
  for (Effect e : out.tied) head.indistinguishable.push_back(e);
}

}  // namespace

StepRanking rank_step(std::vector<Candidate>& all, const RankingContext& context, double margin) {
  StepRanking out;
  const auto ref_it = std::find_if(all.begin(), all.end(), [](const Candidate& c) { return c.reference; });
  const Candidate reference = ref_it != all.end() ? *ref_it : Candidate{};
  const double dispersion = dispersion_of(all);
  out.dispersion = dispersion;
  score_candidates(all, reference, context, dispersion);
  std::stable_sort(all.begin(), all.end(),
                   [](const Candidate& a, const Candidate& b) { return a.score < b.score; });
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (all[i].reference) out.reference = static_cast<int>(i);
    if (out.best < 0 && eligible(all[i])) out.best = static_cast<int>(i);
  }
  if (out.best < 0 || out.reference < 0) return out;
  std::vector<std::vector<double>> chunks;
  for (const Candidate& c : all)
    chunks.push_back(chunk_chi_squares(c, context.flights, context.inverse_sigma));
  measure_against(all, static_cast<std::size_t>(out.best), chunks, dispersion);
  int listed = -1;
  const int in_place = told_apart_best(all, static_cast<std::size_t>(out.best), context, listed);
  if (in_place < 0) {
    out.best = -1;
    return out;
  }
  const std::size_t best = static_cast<std::size_t>(in_place);
  if (static_cast<int>(best) != out.best) measure_against(all, best, chunks, dispersion);
  out.beats_reference = all[best].score < all[static_cast<std::size_t>(out.reference)].score - margin;
  out.equivalent = class_of(all, all[best], context, margin, dispersion);
  const std::size_t head = fixed_order_headline(all, best, context.gyro_input);
  if (head != best) {
    measure_against(all, head, chunks, dispersion);
    out.equivalent = class_of(all, all[head], context, margin, dispersion);
  }
  out.best = static_cast<int>(head);
  for (const Candidate& c : all) {
    const bool fits_as_well = static_cast<int>(&c - all.data()) == listed;
    if (eligible(c) && !contains(out.equivalent, c.effect) &&
        (scores_tie(c.score_behind, c.score_behind_spread) || fits_as_well))
      out.tied.push_back(c.effect);
  }
  std::sort(out.tied.begin(), out.tied.end());
  if (out.beats_reference) mark_indistinguishable(all, out);
  list_ties_in_registry_order(all, out, context.gyro_input);
  return out;
}

void rank_candidates(Analysis& analysis, bool gyro_input, const std::vector<const Flight*>& flights,
                     const std::vector<Eigen::Vector3d>& inverse_sigma, double mean_speed,
                     double duration_s) {
  rank_candidates(
      analysis, RankingContext{gyro_input, flights, inverse_sigma, mean_speed, duration_s, nullptr, 0.0, {}});
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
  v.indistinguishable = step.beats_reference ? step.tied : std::vector<Effect>{};
  if (step.beats_reference) note_ties(v, *chosen, step.tied, all);
  if (step.beats_reference) note_close_minima(analysis, *chosen);
  if (step.beats_reference && !chosen->identifiable) {
    v.confident = false;
    v.could_not_judge.push_back(std::string(effect_name(chosen->effect)) +
                                " explains the gap but its parameters are poorly determined");
  }
}

}  // namespace aloft::host::diagnose
