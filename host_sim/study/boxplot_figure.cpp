#include "study/boxplot_figure.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "study/paper_cylinder.hpp"
#include "study/percentiles.hpp"
#include "study/study_outputs.hpp"

namespace aloft::host {
namespace {

constexpr double kWidth = 1260.0;
constexpr double kRowHeight = 470.0;  // one row of panels per frame
constexpr double kTitleHeight = 40.0;
constexpr double kRowTop = 40.0;      // plot area top, below the row's panel titles
constexpr double kRowBottom = 400.0;  // y of the horizontal axis within a row

struct Box {
  std::string label;
  DistributionSummary summary;
  const paper::PublishedRow* paper = nullptr;
};

struct Panel {
  std::string title;
  double top = 0.0, bottom = 0.0;  // plot area
  std::string x_label;
  double left = 0.0, width = 0.0;
  double y_max = 1.0;
  std::vector<Box> boxes;
};

// Grid step of a DA axis reaching v degrees: the smallest of 1, 2, 5, 10, 20, 50 that
// needs no more than 9 gridlines.
double tick_step(double v) {
  for (double step : {1.0, 2.0, 5.0, 10.0, 20.0}) {
    if (v / step <= 9.0) return step;
  }
  return 50.0;
}

// The top of a DA axis (which starts at 0): 10 % above v, on a whole number of steps of
// the axis' own grid, so that the axis ends on a labelled tick.
double nice_ceiling(double v) {
  double top = std::max(1.0, std::ceil(v * 1.1));
  while (std::fmod(top, tick_step(top)) != 0.0) top += 1.0;
  return top;
}

void text(cairo_t* cr, double x, double y, const std::string& s, double size, double align_x,
          bool bold = false) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  cairo_move_to(cr, x - align_x * e.x_advance, y);
  cairo_show_text(cr, s.c_str());
}

void line(cairo_t* cr, double x0, double y0, double x1, double y1) {
  cairo_move_to(cr, x0, y0);
  cairo_line_to(cr, x1, y1);
  cairo_stroke(cr);
}

void draw_panel(cairo_t* cr, const Panel& p, bool y_title) {
  const double top = p.top, bottom = p.bottom;
  const auto y_of = [&](double v) { return bottom - (bottom - top) * v / p.y_max; };
  // Axes and grid.
  cairo_set_line_width(cr, 1.0);
  const double step = tick_step(p.y_max);
  for (double v = 0.0; v <= p.y_max + 1e-9; v += step) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    line(cr, p.left, y_of(v), p.left + p.width, y_of(v));
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    line(cr, p.left - 4.0, y_of(v), p.left, y_of(v));
    char label[16];
    std::snprintf(label, sizeof label, "%g", v);
    text(cr, p.left - 7.0, y_of(v) + 4.0, label, 11.0, 1.0);
  }
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  line(cr, p.left, top, p.left, bottom);
  line(cr, p.left, bottom, p.left + p.width, bottom);
  text(cr, p.left, top - 14.0, p.title, 15.0, 0.0, true);
  text(cr, p.left + p.width / 2.0, bottom + 42.0, p.x_label, 12.0, 0.5);
  if (y_title) {
    cairo_save(cr);
    cairo_move_to(cr, p.left - 40.0, (top + bottom) / 2.0);
    cairo_rotate(cr, -M_PI / 2.0);
    cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    cairo_set_font_size(cr, 12.0);
    cairo_text_extents_t e;
    cairo_text_extents(cr, "RMS DA of \u03c9 (\u00b0)", &e);
    cairo_rel_move_to(cr, -e.x_advance / 2.0, 0.0);
    cairo_show_text(cr, "RMS DA of \u03c9 (\u00b0)");
    cairo_restore(cr);
  }
  // Boxes.
  const double slot = p.width / static_cast<double>(p.boxes.size());
  const double half = std::min(22.0, slot * 0.22);
  for (std::size_t i = 0; i < p.boxes.size(); ++i) {
    const Box& b = p.boxes[i];
    const double x = p.left + slot * (static_cast<double>(i) + 0.5);
    const DistributionSummary& s = b.summary;
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_set_line_width(cr, 1.2);
    line(cr, x, y_of(s.p10), x, y_of(s.p25));
    line(cr, x, y_of(s.p75), x, y_of(s.p90));
    line(cr, x - half * 0.5, y_of(s.p10), x + half * 0.5, y_of(s.p10));
    line(cr, x - half * 0.5, y_of(s.p90), x + half * 0.5, y_of(s.p90));
    cairo_rectangle(cr, x - half, y_of(s.p75), 2.0 * half, y_of(s.p25) - y_of(s.p75));
    cairo_set_source_rgb(cr, 0.80, 0.87, 0.95);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
    cairo_stroke(cr);
    cairo_set_line_width(cr, 2.2);
    line(cr, x - half, y_of(s.median), x + half, y_of(s.median));
    text(cr, x, bottom + 18.0, b.label, 12.0, 0.5);
    if (b.paper != nullptr) {
      const double px = x + half + 9.0;
      cairo_set_source_rgb(cr, 0.80, 0.10, 0.10);
      cairo_set_line_width(cr, 1.2);
      line(cr, px, y_of(b.paper->p10), px, y_of(b.paper->p90));
      const double ym = y_of(b.paper->median);
      cairo_move_to(cr, px, ym - 5.0);
      cairo_line_to(cr, px + 5.0, ym);
      cairo_line_to(cr, px, ym + 5.0);
      cairo_line_to(cr, px - 5.0, ym);
      cairo_close_path(cr);
      cairo_fill(cr);
    }
  }
}

std::vector<Panel> build_panels(const StudyResult& result, DaFrame frame, double row_top) {
  const bool paper_side = result.built_in;
  const std::vector<Analysis>& analyses = result.flights.front().analyses;
  Panel a;
  a.title = "A";
  a.x_label = paper_side ? "inertia model" : "nominal tensor per flight";
  const Analysis* reference = nullptr;  // drawn at bound 0 in B1-B3
  for (const Analysis& an : analyses) {
    if (an.monte_carlo) continue;
    if (reference == nullptr) reference = &an;
    if (paper_side || result.flights.size() == 1) {
      a.boxes.push_back({an.name, summarise(pooled_rms_da(result, an.name, frame)),
                         paper_side ? published_row(an) : nullptr});
    }
  }
  if (!paper_side && result.flights.size() > 1) {
    for (const FlightStudy& f : result.flights) {
      a.boxes.push_back({f.flight.name, summarise(f.analyses.front().values(frame)), nullptr});
    }
  }
  std::vector<Panel> panels{a};
  const struct {
    PerturbationFamily family;
    const char* title;
    const char* x_label;
  } families[] = {{PerturbationFamily::moments, "B1", "bound on principal moments (\u00b1%)"},
                  {PerturbationFamily::axes, "B2", "bound on principal axes (\u00b1\u00b0)"},
                  {PerturbationFamily::both, "B3", "bound on moments (\u00b1%) and axes (\u00b1\u00b0)"}};
  for (const auto& fam : families) {
    Panel p;
    p.title = fam.title;
    p.x_label = fam.x_label;
    if (reference != nullptr) {
      p.boxes.push_back({"0", summarise(pooled_rms_da(result, reference->name, frame)), nullptr});
    }
    for (const Analysis& an : analyses) {
      if (!an.monte_carlo || an.perturbation.family != fam.family) continue;
      char label[16];
      std::snprintf(label, sizeof label, "%g", an.perturbation.bound);
      p.boxes.push_back({label, summarise(pooled_rms_da(result, an.name, frame)),
                         paper_side ? published_row(an) : nullptr});
    }
    panels.push_back(p);
  }
  // Geometry and scales: A on its own scale (CP is far above the rest), B1-B3 shared.
  double b_max = 0.0, a_max = 0.0;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    for (const Box& b : panels[i].boxes) {
      double top = b.summary.p90;
      if (b.paper != nullptr) top = std::max(top, b.paper->p90);
      (i == 0 ? a_max : b_max) = std::max(i == 0 ? a_max : b_max, top);
    }
  }
  double left = 80.0;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    panels[i].width = i == 0 ? 60.0 + 70.0 * static_cast<double>(panels[i].boxes.size()) : 270.0;
    panels[i].left = left;
    panels[i].y_max = nice_ceiling(i == 0 ? a_max : b_max);
    panels[i].top = row_top + kRowTop;
    panels[i].bottom = row_top + kRowBottom;
    left += panels[i].width + 60.0;
  }
  return panels;
}

double row_top(std::size_t row) { return kTitleHeight + kRowHeight * static_cast<double>(row); }

void draw(cairo_t* cr, const StudyResult& result, double width) {
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_paint(cr);
  for (std::size_t row = 0; row < result.frames.size(); ++row) {
    const DaFrame frame = result.frames[row];
    std::vector<Panel> panels = build_panels(result, frame, row_top(row));
    for (Panel& p : panels) p.title += std::string(" (") + frame_name(frame) + " axes)";
    for (const Panel& p : panels) draw_panel(cr, p, true);
  }
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  const std::string title = "RMS deviation angle of simulated from measured \u03c9, " + result.input +
                            " (box: quartiles, line: median, whiskers: p10-p90" +
                            (result.built_in ? "; red: the paper's median and p10-p90)" : ")");
  text(cr, width / 2.0, 24.0, title, 13.0, 0.5);
}

double figure_width(const StudyResult& result) {
  const std::vector<Panel> panels = build_panels(result, result.frames.front(), 0.0);
  return std::max(kWidth, panels.back().left + panels.back().width + 30.0);
}

}  // namespace

FigureFiles render_study_figure(const StudyResult& result) {
  const double width = figure_width(result);
  const double height = row_top(result.frames.size());
  return render_svg_and_png(
      width, height, [&](cairo_t* cr) { draw(cr, result, width); }, "figure");
}

}  // namespace aloft::host
