// A figure of stacked panels, each lines over a shared kind of x axis with a legend, as
// SVG and PNG (cairo draws both from one drawing): the form of every figure of
// `aloft diagnose --plot`.
#pragma once

#include <string>
#include <vector>

namespace aloft::host::diagnose {

struct Series {
  std::string label;
  std::vector<double> x, y;  // a non-finite y lifts the pen: one series, many strokes
  double r, g, b;
};

struct Panel {
  std::string title, y_label;
  std::vector<Series> series;
  bool from_zero = false;  // a magnitude (DA, relative error): the axis starts at 0
  std::string x_label = "time since release (s)";
};

// Writes STEM.svg and STEM.png, each whole or not at all; throws aloft::host::Error
// naming the file on failure. The x axis spans the data exactly.
void write_figure(const std::vector<Panel>& panels, const std::string& title, const std::string& stem);

}  // namespace aloft::host::diagnose
