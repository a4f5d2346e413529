#include "diagnose/6_report/gap_plot.hpp"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "aloft/dynamics/deviation.hpp"
#include "common/commands.hpp"
#include "diagnose/6_report/panel_figure.hpp"
#include "diagnose/6_report/session_plot.hpp"

namespace aloft::host::diagnose {
namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

std::vector<Panel> panels_of(const FlightDiagnosis& d) {
  const Flight& flight = *d.flight;
  const Analysis& a = d.analysis;
  std::vector<Panel> panels(3);
  panels[0] = {"Deviation angle, held out", "DA (deg)", {}, true};
  panels[1] = {"Relative error, held out", "|\u03c9_sim \u2212 \u03c9_meas| / |\u03c9_meas|", {}, true};
  panels[2] = {"Invariants of the measured motion (nominal tensor)", "change from mean (%)", {}, false};
  auto add_gap = [&](const Candidate& c, const std::string& label, double r, double g, double b) {
    Series da{label, {}, {}, r, g, b}, rel{label, {}, {}, r, g, b};
    for (std::size_t k = 0; k < flight.size(); ++k) {
      const double t = flight.time_s[k] - flight.start_s();
      const bool ok = flight.usable[k] && !c.heldout_readings.empty();
      da.x.push_back(t);
      rel.x.push_back(t);
      da.y.push_back(ok ? deviation_angle<double>(c.heldout_readings[0][k], flight.omega[k]) * kDeg : NAN);
      rel.y.push_back(ok ? relative_error<double>(c.heldout_readings[0][k], flight.omega[k]) : NAN);
    }
    panels[0].series.push_back(da);
    panels[1].series.push_back(rel);
  };
  for (const Candidate& c : a.candidates) {
    if (c.effect == Effect::none) add_gap(c, "nominal model", 0.8, 0.2, 0.1);
  }
  if (a.verdict.chosen >= 0 && a.verdict.effect != Effect::none) {
    add_gap(a.candidates[static_cast<std::size_t>(a.verdict.chosen)],
            std::string("with ") + effect_name(a.verdict.effect), 0.1, 0.3, 0.8);
  }
  if (a.where.invariants) {
    for (const InvariantBehaviour* inv : {&a.where.invariants->energy, &a.where.invariants->momentum}) {
      Series s{inv->name == "kinetic_energy" ? "kinetic energy" : "|L|", {}, {}, 0, 0, 0};
      if (inv->name == "kinetic_energy")
        s.r = 0.9, s.g = 0.5;
      else
        s.g = 0.5, s.b = 0.3;
      for (std::size_t k = 0; k < flight.size(); ++k) {
        s.x.push_back(flight.time_s[k] - flight.start_s());
        s.y.push_back(inv->mean != 0 ? 100.0 * (inv->series[k] / inv->mean - 1.0) : NAN);
      }
      panels[2].series.push_back(s);
    }
  }
  return panels;
}

void make_dir(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error(dir + ": cannot create the plot folder: " + ec.message());
}

std::string safe_name(const std::string& name) {
  std::string out;
  for (char c : name) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  return out;
}

std::string title_of(const FlightDiagnosis& d) {
  return "aloft diagnose: flight " + d.name + " \u2014 verdict " + effect_name(d.analysis.verdict.effect);
}

}  // namespace

void write_flight_plots(const FlightDiagnosis& d, const NominalInertia&, const std::string& dir) {
  make_dir(dir);
  if (d.flight == nullptr || d.analysis.candidates.empty()) return;
  write_figure(panels_of(d), title_of(d), (std::filesystem::path(dir) / "gap").string());
}

void write_session_plots(const SessionDiagnosis& s, const NominalInertia&, const std::string& dir) {
  make_dir(dir);
  write_figure(session_panels(s),
               "aloft diagnose: session of " + std::to_string(s.flights.size()) + " flights",
               (std::filesystem::path(dir) / "session").string());
  for (const FlightDiagnosis& d : s.flights) {
    if (d.flight == nullptr || d.analysis.candidates.empty()) continue;
    write_figure(panels_of(d), title_of(d),
                 (std::filesystem::path(dir) / ("flight_" + safe_name(d.name))).string());
  }
}

}  // namespace aloft::host::diagnose
