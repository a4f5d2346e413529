#include "diagnose/6_report/report_text.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "common/printf_text.hpp"
#include "diagnose/6_report/effect_words.hpp"

namespace aloft::host::diagnose {
namespace {

// gap_over_noise is a chi-square per residual, a squared ratio: 1300 reads as "1300 x the
// noise" but is a gap 36 times the noise floor. Both, and what 1 means.
std::string gap_over_noise_text(double chi_square_per_residual) {
  return printf_text(
      ", %.1f x the noise floor (RMS residual over the noise's; chi-square per sample %.4g, 1 is "
      "noise alone)",
      std::sqrt(std::max(0.0, chi_square_per_residual)), chi_square_per_residual);
}

std::string analysis_summary(const Analysis& a) {
  std::ostringstream out;
  if (a.tensor) out << "  " << tensor_summary(*a.tensor);
  out << printf_text("  baseline (nominal model): RMS DA %.3f deg, RMS relative error %.4f",
                     a.baseline.rms_da_deg, a.baseline.rms_rel_err)
      << gap_over_noise_text(a.where.gap_over_noise) << "\n";
  out << "  where: gap mostly along body " << a.where.dominant_axis;
  if (a.where.onset_s) out << printf_text(", leaves the nominal model at %.3f s", *a.where.onset_s);
  if (a.where.invariants) {
    out << "; energy " << a.where.invariants->energy.behaviour << ", |L| "
        << a.where.invariants->momentum.behaviour;
  }
  out << "\n";
  const Verdict& v = a.verdict;
  out << "  verdict: " << effect_name(v.effect);
  if (v.equivalent.size() > 1) {
    out << " (indistinguishable here from";
    for (std::size_t i = 1; i < v.equivalent.size(); ++i) out << " " << effect_name(v.equivalent[i]);
    out << ")";
  }
  // A tie of scores, or an effect that fits better but is named only where the data tell
  // it apart (4_judge/told_apart.hpp): could_not_judge says which, with the numbers.
  if (!v.indistinguishable.empty()) {
    out << " (not told apart from";
    for (Effect e : v.indistinguishable) out << " " << effect_name(e);
    out << " here: see could not judge)";
  }
  if (!v.effects.empty()) {
    out << ": " << params_text(v.effects.front().effect, v.effects.front().params) << "\n";
    for (std::size_t i = 1; i < v.effects.size(); ++i) {
      out << "  and " << effect_name(v.effects[i].effect) << ": "
          << params_text(v.effects[i].effect, v.effects[i].params)
          << printf_text(" (the model without it: held-out error %.0f %% larger)",
                         100.0 * (1.0 / std::max(1e-9, 1.0 - v.effects[i].shrink) - 1.0))
          << "\n";
    }
    out << printf_text("  held out: RMS DA %.3f -> %.3f deg, relative error %.4f -> %.4f",
                       v.heldout_rms_da_before_deg, v.heldout_rms_da_after_deg, v.heldout_rms_rel_err_before,
                       v.heldout_rms_rel_err_after)
        << printf_text(" (shrink %.0f %%)",
                       100.0 * (v.heldout_rms_rel_err_before > 0
                                    ? 1.0 - v.heldout_rms_rel_err_after / v.heldout_rms_rel_err_before
                                    : 0.0))
        << "\n";
  } else {
    out << printf_text(": the held-out gap (RMS DA %.3f deg) is what the noise explains",
                       v.heldout_rms_da_before_deg)
        << "\n";
  }
  for (const std::string& s : v.could_not_judge) out << "  could not judge: " << s << "\n";
  for (const Note& n : a.notes) out << "  note: " << note_text(n) << "\n";
  return out.str();
}

// Contact cut away from a given segment (1_input/contact.hpp).
std::string contact_text(const Contact& c) {
  return printf_text("contact at %.3f s: %.0f m/s^2 beyond rotation; %.3f to %.3f s cut away", c.at_s,
                     c.beyond_rotation_m_s2, c.cut_from_s, c.cut_to_s) +
         (c.before_release ? " (before the release)" : " (after the landing)");
}

// The body file's rotor as the log gives it at the flight's end (1_input/flight.hpp).
std::string logged_rotor_text(const Flight& f) {
  const Eigen::Vector3d& h = *f.logged_rotor_h_N_m_s;
  return printf_text(
      "the log's rotor at the flight's end: h = (%.3g, %.3g, %.3g) N m s in body axes, |h| %.3g N m s "
      "(the body file's rotor times rotor_rad_s; not in the model: diagnose finds a rotor as "
      "internal_momentum)",
      h(0), h(1), h(2), h.norm());
}

}  // namespace

std::string flight_summary(const FlightDiagnosis& d) {
  std::ostringstream out;
  out << "flight " << d.name
      << printf_text(": %.3f to %.3f s, %.0f samples at %.0f Hz", d.start_s, d.end_s,
                     static_cast<double>(d.samples), d.rate_hz)
      << printf_text(", noise floor %.4f rad/s", d.noise.sigma.mean());
  if (d.unusable_samples) out << ", " << d.unusable_samples << " saturated samples left out";
  if (!d.gaps.empty()) out << ", " << d.gaps.size() << " gaps in its time stamps";
  out << "\n";
  if (d.flight) {
    for (const Contact& c : d.flight->contacts) out << "  " << contact_text(c) << "\n";
    if (d.flight->logged_rotor_h_N_m_s) out << "  " << logged_rotor_text(*d.flight) << "\n";
  }
  out << analysis_summary(d.analysis);
  return out.str();
}

std::string session_summary(const SessionDiagnosis& s) {
  std::ostringstream out;
  out << "session of " << s.flights.size()
      << (s.single_flight ? " flight(s), one judged (its own verdict, held out within the flight)\n"
                          : " flights (pooled, held out: leave one flight out)\n")
      << analysis_summary(s.pooled);
  if (s.flip_period) {
    out << printf_text("  flip period from the first sample, %d flights: mean error %.1f %% nominal",
                       s.flip_period->flights, 100.0 * s.flip_period->mean_error_nominal);
    std::string model;
    for (const VerdictEffect& e : s.pooled.verdict.effects)
      model += (model.empty() ? "" : " + ") + std::string(effect_name(e.effect));
    if (s.flip_period->diagnosed_flights > 0) {
      out << printf_text(", %.1f %% with ", 100.0 * s.flip_period->mean_error_diagnosed) << model
          << " (fitted without each flight)";
    }
    out << "\n";
    if (s.flip_period->fitted_flights > 0) {
      out << printf_text(
                 "  flip period from each flight's fitted initial state, %d flights: mean error %.1f %% "
                 "nominal, ",
                 s.flip_period->fitted_flights, 100.0 * s.flip_period->mean_error_nominal_fitted)
          << printf_text("%.1f %% with ", 100.0 * s.flip_period->mean_error_diagnosed_fitted) << model
          << "\n";
    }
    if (std::max(s.flip_period->mean_error_nominal, s.flip_period->mean_error_diagnosed) > 0.5) {
      out << "  why a flip-period error can be large beside a large shrink: the flip period is the time "
             "between sign changes of the intermediate-axis rate, and near the separatrix (a spin close "
             "to that axis) a tiny error in the rate moves it a lot, however closely the model follows "
             "the measured rates; judge the model by the held-out gap above\n";
    }
  }
  for (const FlightDiagnosis& d : s.flights) {
    const Verdict& v = d.analysis.verdict;
    out << "  flight " << d.name << ": " << effect_name(v.effect)
        << printf_text(" (held-out RMS DA %.2f -> %.2f deg)", v.heldout_rms_da_before_deg,
                       v.heldout_rms_da_after_deg)
        << (v.confident ? "" : " [not confident]");
    if (d.flight && d.flight->logged_rotor_h_N_m_s)
      out << printf_text("; the log's rotor |h| %.3g N m s at its end",
                         d.flight->logged_rotor_h_N_m_s->norm());
    out << "\n";
  }
  return out.str();
}

}  // namespace aloft::host::diagnose
