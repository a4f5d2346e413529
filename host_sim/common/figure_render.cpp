#include "common/figure_render.hpp"

#include <cairo-svg.h>

#include <cmath>

#include "common/commands.hpp"

namespace aloft::host {
namespace {

cairo_status_t append_to_string(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// Draws on `surface` and reports the first error of drawing or of the surface.
cairo_status_t draw_on(cairo_surface_t* surface, const std::function<void(cairo_t*)>& draw) {
  cairo_t* cr = cairo_create(surface);
  draw(cr);
  const cairo_status_t status = cairo_status(cr);
  cairo_destroy(cr);
  return status;
}

}  // namespace

FigureFiles render_svg_and_png(double width, double height, const std::function<void(cairo_t*)>& draw,
                               const std::string& name) {
  FigureFiles files;
  cairo_surface_t* svg = cairo_svg_surface_create_for_stream(append_to_string, &files.svg, width, height);
  cairo_status_t status = draw_on(svg, draw);
  cairo_surface_finish(svg);
  if (status == CAIRO_STATUS_SUCCESS) status = cairo_surface_status(svg);
  cairo_surface_destroy(svg);
  if (status != CAIRO_STATUS_SUCCESS) throw Error(name + ".svg: " + cairo_status_to_string(status));

  cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_RGB24, static_cast<int>(std::ceil(width)),
                                                      static_cast<int>(std::ceil(height)));
  status = draw_on(image, draw);
  if (status == CAIRO_STATUS_SUCCESS) {
    status = cairo_surface_write_to_png_stream(image, append_to_string, &files.png);
  }
  cairo_surface_destroy(image);
  if (status != CAIRO_STATUS_SUCCESS) throw Error(name + ".png: " + cairo_status_to_string(status));
  return files;
}

}  // namespace aloft::host
