// One picture drawn twice with cairo, into an SVG and a PNG, both kept in memory so a
// command writes both files or neither (see atomic_file.hpp). The study's boxplots and
// the diagnosis's gap plots are drawn through this.
#pragma once

#include <cairo.h>

#include <functional>
#include <string>

namespace aloft::host {

struct FigureFiles {
  std::string svg;
  std::string png;
};

// Calls `draw` once on an SVG surface and once on an RGB image of width x height points,
// and returns both encodings. Throws aloft::host::Error naming `name` if cairo fails.
FigureFiles render_svg_and_png(double width, double height, const std::function<void(cairo_t*)>& draw,
                               const std::string& name);

}  // namespace aloft::host
