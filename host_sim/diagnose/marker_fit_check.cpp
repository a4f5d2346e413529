#include "diagnose/marker_fit_check.hpp"

#include <cstdio>

namespace aloft::host::diagnose {

std::optional<std::string> marker_misfit(const PoseFitReport& report) {
  if (!(report.mean_rms_residual_m > kLargestMarkerResidual_m)) return std::nullopt;
  char text[320];
  std::snprintf(text, sizeof text,
                "the body's markers do not fit this trial: mean pose-fit residual %.1f mm (marker noise gives "
                "well under 1 mm); check the body file's marker positions, names and the file's units",
                report.mean_rms_residual_m * 1000.0);
  return std::string(text);
}

}  // namespace aloft::host::diagnose
