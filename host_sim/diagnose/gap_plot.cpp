#include "diagnose/gap_plot.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <ostream>

#include "aloft/deviation.hpp"
#include "common/atomic_file.hpp"
#include "common/figure_render.hpp"
#include "common/commands.hpp"

namespace aloft::host::diagnose {
namespace {

constexpr double kWidth = 900, kHeight = 780;
constexpr double kDeg = 180.0 / 3.14159265358979323846;

struct Series {
  std::string label;
  std::vector<double> x, y;
  double r, g, b;
};

struct Panel {
  std::string title, y_label;
  std::vector<Series> series;
};

void draw_panel(cairo_t* cr, const Panel& panel, double top, double height) {
  const double left = 80, right = kWidth - 20;
  const double plot_top = top + 28, plot_bottom = top + height - 36;
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const Series& s : panel.series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.y[i])) continue;
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]);
      y1 = std::max(y1, s.y[i]);
    }
  }
  if (!(x1 > x0)) x1 = x0 + 1;
  if (!(y1 > y0)) y1 = y0 + 1;
  const double pad = 0.05 * (y1 - y0);
  y0 -= pad;
  y1 += pad;
  auto px = [&](double x) { return left + (x - x0) / (x1 - x0) * (right - left); };
  auto py = [&](double y) { return plot_bottom - (y - y0) / (y1 - y0) * (plot_bottom - plot_top); };

  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, 14);
  cairo_move_to(cr, left, top + 18);
  cairo_show_text(cr, panel.title.c_str());
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 11);
  cairo_set_line_width(cr, 1);
  cairo_rectangle(cr, left, plot_top, right - left, plot_bottom - plot_top);
  cairo_stroke(cr);
  char text[64];
  for (int i = 0; i <= 4; ++i) {
    const double y = y0 + (y1 - y0) * i / 4.0;
    std::snprintf(text, sizeof text, "%.3g", y);
    cairo_move_to(cr, 8, py(y) + 4);
    cairo_show_text(cr, text);
    const double x = x0 + (x1 - x0) * i / 4.0;
    std::snprintf(text, sizeof text, "%.3f", x);
    cairo_move_to(cr, px(x) - 14, plot_bottom + 16);
    cairo_show_text(cr, text);
  }
  cairo_move_to(cr, (left + right) / 2 - 20, plot_bottom + 30);
  cairo_show_text(cr, "time (s)");
  cairo_move_to(cr, 8, plot_top - 6);
  cairo_show_text(cr, panel.y_label.c_str());
  double legend_x = right - 260;
  for (const Series& s : panel.series) {
    cairo_set_source_rgb(cr, s.r, s.g, s.b);
    cairo_set_line_width(cr, 1.2);
    bool pen_down = false;
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.y[i])) {
        pen_down = false;
        continue;
      }
      if (pen_down) {
        cairo_line_to(cr, px(s.x[i]), py(s.y[i]));
      } else {
        cairo_move_to(cr, px(s.x[i]), py(s.y[i]));
        pen_down = true;
      }
    }
    cairo_stroke(cr);
    cairo_rectangle(cr, legend_x, top + 8, 14, 4);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, legend_x + 18, top + 14);
    cairo_show_text(cr, s.label.c_str());
    legend_x += 130;
  }
}

std::vector<Panel> panels_of(const FlightDiagnosis& d) {
  const Flight& flight = *d.flight;
  const Analysis& a = d.analysis;
  std::vector<Panel> panels(3);
  panels[0] = {"Deviation angle, held out", "DA (deg)", {}};
  panels[1] = {"Relative error, held out", "|w_sim - w_meas| / |w_meas|", {}};
  panels[2] = {"Invariants of the measured motion (nominal tensor)", "relative to mean (%)", {}};
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
      if (inv->name == "kinetic_energy") s.r = 0.9, s.g = 0.5;
      else s.g = 0.5, s.b = 0.3;
      for (std::size_t k = 0; k < flight.size(); ++k) {
        s.x.push_back(flight.time_s[k] - flight.start_s());
        s.y.push_back(inv->mean != 0 ? 100.0 * (inv->series[k] / inv->mean - 1.0) : NAN);
      }
      panels[2].series.push_back(s);
    }
  }
  return panels;
}

void draw(cairo_t* cr, const std::vector<Panel>& panels, const std::string& title) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, 15);
  cairo_move_to(cr, 20, 22);
  cairo_show_text(cr, title.c_str());
  const double height = (kHeight - 30) / static_cast<double>(panels.size());
  for (std::size_t i = 0; i < panels.size(); ++i) draw_panel(cr, panels[i], 30 + height * i, height);
}

void write_bytes(const std::string& path, const std::string& bytes) {
  write_file_atomically(path, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

void write_figure(const std::vector<Panel>& panels, const std::string& title, const std::string& stem) {
  const FigureFiles files = render_svg_and_png(
      kWidth, kHeight, [&](cairo_t* cr) { draw(cr, panels, title); }, stem);
  write_bytes(stem + ".svg", files.svg);
  write_bytes(stem + ".png", files.png);
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
  return "aloft diagnose: flight " + d.name + " -- verdict " + effect_name(d.analysis.verdict.effect);
}

}  // namespace

void write_flight_plots(const FlightDiagnosis& d, const NominalInertia&, const std::string& dir) {
  make_dir(dir);
  if (d.flight == nullptr || d.analysis.candidates.empty()) return;
  write_figure(panels_of(d), title_of(d), (std::filesystem::path(dir) / "gap").string());
}

void write_session_plots(const SessionDiagnosis& s, const NominalInertia&, const std::string& dir) {
  make_dir(dir);
  for (const FlightDiagnosis& d : s.flights) {
    if (d.flight == nullptr || d.analysis.candidates.empty()) continue;
    write_figure(panels_of(d), title_of(d), (std::filesystem::path(dir) / ("flight_" + safe_name(d.name))).string());
  }
}

}  // namespace aloft::host::diagnose
