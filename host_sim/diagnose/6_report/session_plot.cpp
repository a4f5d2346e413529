#include "diagnose/6_report/session_plot.hpp"

#include <cmath>
#include <string>

namespace aloft::host::diagnose {
namespace {

// A horizontal line at y from x0 to x1, then a lifted pen.
void add_level(Series& s, double x0, double x1, double y) {
  s.x.insert(s.x.end(), {x0, x1, x1});
  s.y.insert(s.y.end(), {y, y, NAN});
}

Panel ratio_panel(const SessionDiagnosis& session, int which) {
  const char* name = which == 0 ? "I2/I1" : "I3/I1";
  Panel p{std::string("Moment ratio ") + name + ": each flight's 95 % interval and the pooled one",
          name,
          {},
          false,
          "flight (in the order of the segments file)"};
  Series flights{"flights' 95 %", {}, {}, 0.1, 0.3, 0.8}, best{"flights' best", {}, {}, 0.0, 0.0, 0.0};
  const double n = static_cast<double>(session.flights.size());
  for (std::size_t i = 0; i < session.flights.size(); ++i) {
    const auto& tensor = session.flights[i].analysis.tensor;
    if (!tensor) continue;
    const double x = static_cast<double>(i + 1);
    flights.x.insert(flights.x.end(), {x, x, x});
    flights.y.insert(flights.y.end(), {tensor->ratio_low(which), tensor->ratio_high(which), NAN});
    add_level(best, x - 0.15, x + 0.15, tensor->ratio_best(which));
  }
  p.series = {flights, best};
  if (const auto& pooled = session.pooled.tensor) {
    Series band{"pooled 95 %", {}, {}, 0.2, 0.6, 0.2}, nominal{"body file", {}, {}, 0.8, 0.2, 0.1};
    add_level(band, 0.6, n + 0.4, pooled->ratio_low(which));
    add_level(band, 0.6, n + 0.4, pooled->ratio_high(which));
    add_level(nominal, 0.6, n + 0.4, pooled->ratio_nominal(which));
    p.series.push_back(band);
    p.series.push_back(nominal);
  }
  return p;
}

// Measured ω and the nominal model's held-out simulation of it, flights laid end to end
// with a short break between them.
Panel omega_panel(const SessionDiagnosis& session) {
  Panel p{"\u03c9 measured (dark), simulated by the nominal model (light, held out)",
          "\u03c9 (rad/s)",
          {},
          false,
          "time in flight, flights one after another (s)"};
  const char* axis[] = {"x", "y", "z"};
  const double dark[3][3] = {{0.8, 0.1, 0.1}, {0.1, 0.5, 0.1}, {0.1, 0.2, 0.8}};
  std::vector<Series> measured, simulated;
  for (int k = 0; k < 3; ++k) {
    measured.push_back({std::string("\u03c9") + axis[k], {}, {}, dark[k][0], dark[k][1], dark[k][2]});
    simulated.push_back({std::string("sim ") + axis[k],
                         {},
                         {},
                         0.5 + 0.5 * dark[k][0],
                         0.5 + 0.5 * dark[k][1],
                         0.5 + 0.5 * dark[k][2]});
  }
  double offset = 0.0;
  for (const FlightDiagnosis& d : session.flights) {
    if (d.flight == nullptr) continue;
    const Flight& f = *d.flight;
    const Candidate* none = nullptr;
    for (const Candidate& c : d.analysis.candidates) {
      if (c.effect == Effect::none && !c.heldout_readings.empty()) none = &c;
    }
    for (std::size_t i = 0; i < f.size(); ++i) {
      const double t = offset + f.time_s[i] - f.start_s();
      for (int k = 0; k < 3; ++k) {
        measured[k].x.push_back(t);
        measured[k].y.push_back(f.omega[i](k));
        simulated[k].x.push_back(t);
        simulated[k].y.push_back(none && f.usable[i] ? none->heldout_readings[0][i](k) : NAN);
      }
    }
    for (int k = 0; k < 3; ++k) measured[k].y.back() = simulated[k].y.back() = NAN;  // lift between flights
    offset += f.end_s() - f.start_s() + 0.1;
  }
  for (int k = 0; k < 3; ++k) p.series.push_back(simulated[k]);
  for (int k = 0; k < 3; ++k) p.series.push_back(measured[k]);
  return p;
}

}  // namespace

std::vector<Panel> session_panels(const SessionDiagnosis& session) {
  return {ratio_panel(session, 0), ratio_panel(session, 1), omega_panel(session)};
}

}  // namespace aloft::host::diagnose
