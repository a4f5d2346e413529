#include "diagnose/6_report/report_json.hpp"

#include <cmath>
#include <string>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/6_report/effect_words.hpp"
#include "diagnose/6_report/json_values.hpp"

namespace aloft::host::diagnose {
namespace {

using nlohmann::json;

json names(const std::vector<Effect>& effects) {
  json out = json::array();
  for (Effect e : effects) out.push_back(effect_name(e));
  return out;
}

json invariant_json(const InvariantBehaviour& b) {
  return {{"mean", b.mean},
          {"relative_change", b.relative_change},
          {"relative_oscillation", b.relative_oscillation},
          {"behaviour", b.behaviour}};
}

// The whole final model's parameters: each effect's keys (SPEC keys never collide
// between effects that can share a model).
json model_params_json(const Verdict& v) {
  json out = json::object();
  for (const VerdictEffect& e : v.effects) {
    const json params = params_json(e.effect, e.params);
    for (auto it = params.begin(); it != params.end(); ++it) {
      if (!out.contains(it.key())) out[it.key()] = it.value();
    }
  }
  return out;
}

json verdict_effects_json(const Verdict& v) {
  json out = json::array();
  for (const VerdictEffect& e : v.effects) {
    out.push_back({{"effect", effect_name(e.effect)},
                   {"equivalent", names(e.equivalent)},
                   {"indistinguishable_from", names(e.indistinguishable)},
                   {"params", params_json(e.effect, e.params)},
                   {"heldout_rms_rel_err_after", e.heldout_rms_rel_err_after},
                   {"heldout_rms_da_after_deg", e.heldout_rms_da_after_deg},
                   {"shrink", e.shrink},
                   {"step", e.step},
                   {"step_shrink", e.step_shrink}});
  }
  return out;
}

// Each step of the stepwise selection: the model it started from, what joined (null:
// nothing did, the selection stopped), the held-out gap before and after, and the
// candidate additions it weighed.
json steps_json(const Analysis& a) {
  json out = json::array();
  for (std::size_t i = 0; i < a.steps.size(); ++i) {
    const ModelStep& s = a.steps[i];
    const std::vector<Candidate>& candidates = i == 0 ? a.candidates : s.candidates;
    json step = {
        {"model", names(s.model)},
        {"added", s.added >= 0 ? json(effect_name(candidates[static_cast<std::size_t>(s.added)].effect))
                               : json(nullptr)},
        {"equivalent", names(s.equivalent)},
        {"indistinguishable_from", names(s.indistinguishable)},
        {"heldout_rms_rel_err_before", s.heldout_rms_rel_err_before},
        {"heldout_rms_rel_err_after", s.heldout_rms_rel_err_after},
        {"heldout_rms_da_before_deg", s.heldout_rms_da_before_deg},
        {"heldout_rms_da_after_deg", s.heldout_rms_da_after_deg},
        {"shrink", s.shrink}};
    // A pair of the first step (4_judge/joint_candidates.hpp) adds the effects fitted with it.
    if (s.added >= 0 && !candidates[static_cast<std::size_t>(s.added)].base.empty() && i == 0)
      step["added_with"] = names(candidates[static_cast<std::size_t>(s.added)].base);
    if (i > 0) {
      json tried = json::array();
      for (const Candidate& c : s.candidates) {
        if (c.reference || !c.evaluated) continue;
        tried.push_back({{"effect", effect_name(c.effect)},
                         {"heldout_rms_rel_err", c.heldout_rms_rel_err},
                         {"shrink", c.shrink},
                         {"score", c.score},
                         {"score_spread", c.score_spread},
                         {"score_behind", c.score_behind},
                         {"score_behind_spread", c.score_behind_spread},
                         {"physical", c.physical}});
      }
      step["candidates"] = tried;
    }
    out.push_back(step);
  }
  return out;
}

// Near-symmetric bodies (tensor_report.hpp): each plane whose axes the data do not fix.
json unresolved_planes_json(const TensorReport& t) {
  static const char* axis[] = {"x", "y", "z"};
  json out = json::array();
  for (const auto& [a, b] : t.unresolved_planes) {
    out.push_back(
        {{"axes", {axis[a], axis[b]}}, {"moments_kg_m2", {t.moments_kg_m2(a), t.moments_kg_m2(b)}}});
  }
  return out;
}

json tensor_json(const TensorReport& t) {
  static const char* axis[] = {"x", "y", "z"};
  return {
      {"consistent_with_nominal", t.consistent_with_nominal},
      {"ratio_best", {t.ratio_best(0), t.ratio_best(1)}},
      {"ratio_95", {{t.ratio_low(0), t.ratio_high(0)}, {t.ratio_low(1), t.ratio_high(1)}}},
      {"axes_95_deg", t.axes_known ? json(t.axes_95_deg) : json(nullptr)},
      {"ratio_nominal", {t.ratio_nominal(0), t.ratio_nominal(1)}},
      {"ratios", {std::string("I") + axis[1] + "/I" + axis[0], std::string("I") + axis[2] + "/I" + axis[0]}},
      {"flights", t.flights},
      {"method", t.method},
      {"unresolved_planes", unresolved_planes_json(t)}};
}

// Every candidate of the first step, best first.
json candidates_json(const Analysis& a) {
  json candidates = json::array();
  for (const Candidate& c : a.candidates) {
    json j;
    j["effect"] = effect_name(c.effect);
    // A pair fitted together (4_judge/joint_candidates.hpp): the effects fitted with it.
    if (!c.base.empty()) j["with"] = names(c.base);
    j["evaluated"] = c.evaluated;
    if (c.evaluated) {
      j["params"] = params_json(c.effect, c.params);
      j["heldout_rms_da_deg"] = c.heldout_rms_da_deg;
      j["heldout_rms_rel_err"] = c.heldout_rms_rel_err;
      j["shrink"] = c.shrink;
      j["shrink_da"] = c.shrink_da;
      j["heldout_chi_square_per_residual"] =
          c.heldout_residuals ? c.heldout_chi_square / c.heldout_residuals : 0.0;
      j["parameter_count"] = penalty_count(c);
      j["score"] = c.score;
      j["score_spread"] = c.score_spread;
      j["score_behind"] = c.score_behind;
      j["score_behind_spread"] = c.score_behind_spread;
      j["identifiable"] = c.identifiable;
      j["physical"] = c.physical;
      j["indistinguishable_from"] = names(c.indistinguishable);
      json alternatives = json::array();
      for (const Candidate::Alternative& alt : c.alternatives) {
        alternatives.push_back(
            {{"params", params_json(c.effect, alt.params)}, {"cost_behind", alt.cost_behind}});
      }
      j["alternatives"] = alternatives;
    } else {
      j["params"] = json::object();
      j["heldout_rms_da_deg"] = nullptr;
      j["heldout_rms_rel_err"] = nullptr;
      j["shrink"] = nullptr;
    }
    if (!c.note.empty()) j["note"] = c.note;
    candidates.push_back(j);
  }
  return candidates;
}

json analysis_json(const Analysis& a) {
  json out;
  if (a.tensor) out["tensor"] = tensor_json(*a.tensor);
  out["baseline"] = {{"rms_da_deg", a.baseline.rms_da_deg}, {"rms_rel_err", a.baseline.rms_rel_err}};
  json where;
  where["onset_s"] = a.where.onset_s ? json(*a.where.onset_s) : json(nullptr);
  where["dominant_axis"] = a.where.dominant_axis;
  where["rms_gap_body_rad_s"] = json_vec(a.where.rms_gap_body_rad_s);
  where["noise_floor_rad_s"] = json_vec(a.where.noise_floor);
  where["gap_over_noise"] = a.where.gap_over_noise;
  json slices = json::array();
  for (const TimeSlice& s : a.where.slices) {
    slices.push_back({{"from_s", s.from_s},
                      {"to_s", s.to_s},
                      {"rms_da_deg", s.rms_da_deg},
                      {"rms_rel_err", s.rms_rel_err}});
  }
  where["gap_by_time"] = slices;
  if (a.where.invariants) {
    where["invariants"] = {{"kinetic_energy", invariant_json(a.where.invariants->energy)},
                           {"angular_momentum", invariant_json(a.where.invariants->momentum)}};
  }
  out["where"] = where;
  out["candidates"] = candidates_json(a);
  const Verdict& v = a.verdict;
  json verdict;
  verdict["effect"] = effect_name(v.effect);
  verdict["equivalent"] = names(v.equivalent);
  verdict["indistinguishable_from"] = names(v.indistinguishable);
  verdict["params"] = model_params_json(v);
  verdict["heldout_rms_da_before_deg"] = v.heldout_rms_da_before_deg;
  verdict["heldout_rms_da_after_deg"] = v.heldout_rms_da_after_deg;
  verdict["heldout_rms_rel_err_before"] = v.heldout_rms_rel_err_before;
  verdict["heldout_rms_rel_err_after"] = v.heldout_rms_rel_err_after;
  verdict["confident"] = v.confident;
  verdict["could_not_judge"] = v.could_not_judge;
  verdict["effects"] = verdict_effects_json(v);
  verdict["shrink"] = v.heldout_rms_rel_err_before > 0
                          ? 1.0 - v.heldout_rms_rel_err_after / v.heldout_rms_rel_err_before
                          : 0.0;
  verdict["steps"] = steps_json(a);
  out["verdict"] = verdict;
  out["unexplained_dispersion"] = a.dispersion;
  for (const Note& n : a.notes) out["notes"].push_back(note_text(n));
  return out;
}

// Contact cut away from a given segment (1_input/contact.hpp).
json contact_json(const std::vector<Contact>& contacts) {
  json out = json::array();
  for (const Contact& c : contacts) {
    out.push_back({{"where", c.before_release ? "before release" : "after landing"},
                   {"cut_from_s", c.cut_from_s},
                   {"cut_to_s", c.cut_to_s},
                   {"at_s", c.at_s},
                   {"beyond_rotation_m_s2", c.beyond_rotation_m_s2}});
  }
  return out;
}

}  // namespace

json flight_report(const FlightDiagnosis& d) {
  json out = analysis_json(d.analysis);
  out["segment"] = d.name;
  out["start_s"] = d.start_s;
  out["end_s"] = d.end_s;
  out["samples"] = d.samples;
  out["rate_hz"] = d.rate_hz;
  out["noise_floor"] = {{"sigma_rad_s", json_vec(d.noise.sigma)},
                        {"method", d.noise.method},
                        {"resolution_rad_s", d.noise.resolution},
                        {"reliable", d.noise.reliable}};
  // Only where the spectrum gave the floor or its correlation (a fast gyro's rest: noise_floor.cpp);
  // elsewhere the noise is taken as white.
  if (std::string(d.noise.method) == "spectrum" || d.noise.low_pass_hz > 0.0) {
    out["noise_floor"]["readings_per_independent_sample"] = d.noise.correlation;
    out["noise_floor"]["low_pass_hz"] = d.noise.low_pass_hz;
    out["noise_floor"]["low_pass_order"] = d.noise.low_pass_order;
    out["noise_floor"]["low_pass_shape"] = d.noise.low_pass_shape;
  }
  out["unusable_samples"] = d.unusable_samples;
  if (!d.comment.empty()) out["comment"] = d.comment;
  if (d.flight && !d.flight->contacts.empty()) out["contact"] = contact_json(d.flight->contacts);
  if (d.flight && d.flight->logged_rotor_h_N_m_s)
    out["logged_rotor_h_N_m_s"] = json_vec(*d.flight->logged_rotor_h_N_m_s);
  if (d.flip_period) {
    json fp = {{"measured_s", d.flip_period->measured_s},
               {"nominal_s", d.flip_period->nominal_s},
               {"nominal_relative_error", d.flip_period->nominal_error()}};
    if (d.flip_period->diagnosed_s) {
      fp["diagnosed_s"] = *d.flip_period->diagnosed_s;
      fp["diagnosed_relative_error"] =
          std::abs(*d.flip_period->diagnosed_s - d.flip_period->measured_s) / d.flip_period->measured_s;
    }
    const auto& fitted = d.flip_period->nominal_fitted_s;
    if (fitted) fp["nominal_fitted_s"] = *fitted;
    if (fitted) fp["nominal_fitted_relative_error"] = d.flip_period->error(*fitted);
    const auto& diagnosed_fitted = d.flip_period->diagnosed_fitted_s;
    if (diagnosed_fitted) fp["diagnosed_fitted_s"] = *diagnosed_fitted;
    if (diagnosed_fitted) fp["diagnosed_fitted_relative_error"] = d.flip_period->error(*diagnosed_fitted);
    out["flip_period"] = fp;
  }
  json gaps = json::array();
  for (const TimeGap& g : d.gaps) gaps.push_back({{"from_s", g.from_s}, {"to_s", g.to_s}});
  out["time_gaps"] = gaps;
  return out;
}

json session_report(const SessionDiagnosis& s) {
  json out = analysis_json(s.pooled);
  out["heldout"] = s.single_flight ? "within_the_flight" : "leave_one_flight_out";
  json flights = json::array();
  for (const FlightDiagnosis& d : s.flights) flights.push_back(flight_report(d));
  out["flights"] = flights;
  if (s.flip_period) {
    out["flip_period"] = {
        {"flights", s.flip_period->flights},
        {"mean_relative_error_nominal", s.flip_period->mean_error_nominal},
        {"mean_relative_error_diagnosed", s.flip_period->mean_error_diagnosed},
        {"diagnosed_flights", s.flip_period->diagnosed_flights},
        {"mean_relative_error_nominal_fitted", s.flip_period->mean_error_nominal_fitted},
        {"mean_relative_error_diagnosed_fitted", s.flip_period->mean_error_diagnosed_fitted},
        {"fitted_flights", s.flip_period->fitted_flights},
        {"method",
         "point method on the intermediate-axis rate, simulation from the first sample "
         "(*_fitted: from the flight's fitted initial state, model fitted without it)"}};
  }
  return out;
}

}  // namespace aloft::host::diagnose
