#include "diagnose/1_input/marker_fit_check.hpp"

#include <cstdio>

#include "common/commands.hpp"

namespace aloft::host::diagnose {

namespace {

// The body without its marker whose own residual is the largest.
Body without_worst_marker(const Body& body, const PoseFitReport& report, std::string& dropped,
                          double& dropped_residual_m) {
  std::size_t worst = 0;
  for (std::size_t m = 1; m < report.marker_rms_residual_m.size(); ++m) {
    if (report.marker_rms_residual_m[m] > report.marker_rms_residual_m[worst]) worst = m;
  }
  dropped = report.marker_names[worst];
  dropped_residual_m = report.marker_rms_residual_m[worst];
  Body fewer = body;
  fewer.markers_m.erase(dropped);
  return fewer;
}

// "M3 (21.4 mm), M5 (9.0 mm)": the markers whose removal makes the rest fit, dropped
// worst first and refitted each time (least squares spreads one misplaced marker's
// error over the others, so the largest residual alone can name an innocent one too).
// "" when the rest never fit with at most half of the set and three markers left: then
// none stands out (a scale, the units or another marker set).
std::string markers_that_do_not_fit(const MarkerTrial& trial, const Body& body, PoseFitReport report) {
  Body remaining = body;
  std::string named;
  const std::size_t most = body.markers_m.size() / 2;
  for (std::size_t dropped = 0; dropped < most && remaining.markers_m.size() > 3; ++dropped) {
    std::string name;
    double residual_m = 0.0;
    remaining = without_worst_marker(remaining, report, name, residual_m);
    char one[96];
    std::snprintf(one, sizeof one, "%s%s (%.1f mm)", named.empty() ? "" : ", ", name.c_str(),
                  residual_m * 1000.0);
    named += one;
    try {
      fit_poses(trial, remaining, &report);
    } catch (const Error&) {
      return "";  // too few markers left to pose frames: nothing to conclude
    }
    if (report.mean_rms_residual_m <= kLargestMarkerResidual_m) return named;
  }
  return "";
}

}  // namespace

std::optional<std::string> marker_misfit(const MarkerTrial& trial, const Body& body,
                                         const PoseFitReport& report) {
  if (!(report.mean_rms_residual_m > kLargestMarkerResidual_m)) return std::nullopt;
  const std::string culprits = markers_that_do_not_fit(trial, body, report);
  char text[256];
  std::snprintf(
      text, sizeof text,
      "the body's markers do not fit this trial: mean pose-fit residual %.1f mm (marker noise gives "
      "well under 1 mm); ",
      report.mean_rms_residual_m * 1000.0);
  if (culprits.empty()) {
    return std::string(text) +
           "no marker stands out, so check the file's units and the body file's marker positions (scale, "
           "axes)";
  }
  return std::string(text) + "the markers that do not fit: " + culprits +
         "; check their positions and labels in the body file";
}

}  // namespace aloft::host::diagnose
