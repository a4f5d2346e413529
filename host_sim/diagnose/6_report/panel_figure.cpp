#include "diagnose/6_report/panel_figure.hpp"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <ostream>

#include "common/atomic_file.hpp"
#include "common/axis_ticks.hpp"
#include "common/figure_render.hpp"

namespace aloft::host::diagnose {
namespace {

constexpr double kWidth = 900, kHeight = 780;

void show_text_at(cairo_t* cr, double x, double y, const std::string& text) {
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  return e.x_advance;
}

// Smallest and largest finite values of the series along x (first) and y (second).
std::pair<std::pair<double, double>, std::pair<double, double>> data_range(const Panel& panel) {
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
  if (!std::isfinite(x0)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
  return {{x0, x1}, {y0, y1}};
}

// Ticks and tick labels on both axes, the axis titles, the frame.
void draw_axes(cairo_t* cr, const Panel& panel, const AxisTicks& xt, const AxisTicks& yt, double left,
               double right, double plot_top, double plot_bottom, const std::function<double(double)>& px,
               const std::function<double(double)>& py) {
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 11);
  cairo_set_line_width(cr, 1);
  cairo_rectangle(cr, left, plot_top, right - left, plot_bottom - plot_top);
  cairo_stroke(cr);
  for (double y : yt.values) {
    const std::string label = tick_label(y, yt.decimals);
    show_text_at(cr, left - 6 - text_width(cr, label), py(y) + 4, label);
    cairo_move_to(cr, left - 3, py(y));
    cairo_line_to(cr, left, py(y));
  }
  for (double x : xt.values) {
    const std::string label = tick_label(x, xt.decimals);
    show_text_at(cr, px(x) - text_width(cr, label) / 2, plot_bottom + 15, label);
    cairo_move_to(cr, px(x), plot_bottom);
    cairo_line_to(cr, px(x), plot_bottom + 3);
  }
  cairo_stroke(cr);
  show_text_at(cr, right - text_width(cr, panel.x_label), plot_bottom + 30, panel.x_label);
  // The y title runs up the left margin, clear of the tick labels.
  cairo_save(cr);
  cairo_move_to(cr, 16, (plot_top + plot_bottom) / 2 + text_width(cr, panel.y_label) / 2);
  cairo_rotate(cr, -M_PI / 2);
  cairo_show_text(cr, panel.y_label.c_str());
  cairo_restore(cr);
}

void draw_panel(cairo_t* cr, const Panel& panel, double top, double height) {
  const double left = 80, right = kWidth - 20;
  const double plot_top = top + 28, plot_bottom = top + height - 40;
  const auto [x_range, y_range] = data_range(panel);
  // The time axis spans the flight exactly; the y axis ends on round ticks.
  const bool has_span = x_range.second > x_range.first;
  const AxisTicks xt = has_span ? ticks_within(x_range.first, x_range.second, 8) : round_ticks(0.0, 1.0, 8);
  const AxisTicks yt = round_ticks(panel.from_zero ? 0.0 : y_range.first, y_range.second, 4);
  const double x0 = has_span ? x_range.first : xt.first(), x1 = has_span ? x_range.second : xt.last();
  const double y0 = yt.first(), y1 = yt.last();
  const std::function<double(double)> px = [&](double x) {
    return left + (x - x0) / (x1 - x0) * (right - left);
  };
  const std::function<double(double)> py = [&](double y) {
    return plot_bottom - (y - y0) / (y1 - y0) * (plot_bottom - plot_top);
  };

  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, 14);
  show_text_at(cr, left, top + 18, panel.title);
  draw_axes(cr, panel, xt, yt, left, right, plot_top, plot_bottom, px, py);

  // The legend on the title's line, right-aligned, entries laid out by their widths; inside
  // the plot's top right corner if the title leaves no room.
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  cairo_set_font_size(cr, 14);
  const double title_end = left + text_width(cr, panel.title) + 20;
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 11);
  double legend_x = right;
  for (const Series& s : panel.series) legend_x -= 18 + text_width(cr, s.label) + 16;
  const double legend_y = legend_x >= title_end ? top + 10 : plot_top + 8;
  if (legend_x < title_end) legend_x -= 8;
  for (const Series& s : panel.series) {
    cairo_set_source_rgb(cr, s.r, s.g, s.b);
    cairo_set_line_width(cr, 1.2);
    cairo_new_path(cr);
    cairo_rectangle(cr, left, plot_top, right - left, plot_bottom - plot_top);
    cairo_save(cr);
    cairo_clip(cr);
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
    cairo_restore(cr);
    cairo_rectangle(cr, legend_x, legend_y, 14, 4);
    cairo_fill(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    show_text_at(cr, legend_x + 18, legend_y + 6, s.label);
    legend_x += 18 + text_width(cr, s.label) + 16;
  }
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
  write_file_atomically(
      path, [&](std::ostream& out) { out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())); });
}

}  // namespace

void write_figure(const std::vector<Panel>& panels, const std::string& title, const std::string& stem) {
  const FigureFiles files = render_svg_and_png(
      kWidth, kHeight, [&](cairo_t* cr) { draw(cr, panels, title); }, stem);
  write_bytes(stem + ".svg", files.svg);
  write_bytes(stem + ".png", files.png);
}

}  // namespace aloft::host::diagnose
