#include "study/throw_options.hpp"

#include <cmath>

#include "common/commands.hpp"
#include "study/throw_presets.hpp"

namespace aloft::host {
namespace {

bool given(double v) { return !std::isnan(v); }

// Applies `value` when given, after checking it lies in [low, high].
void apply(double value, const char* option, double low, double high, double& into) {
  if (!given(value)) return;
  if (!std::isfinite(value) || value < low || value > high) {
    char range[96];
    std::snprintf(range, sizeof range, "%g to %g", low, high);
    throw Error(std::string("study: ") + option + " must be " + range);
  }
  into = value;
}

}  // namespace

bool ThrowOptions::throw_given() const {
  return searched_given() || given(duration_s) || !marker_layout.empty();
}

bool ThrowOptions::searched_given() const {
  return preset != "built-in" || given(spin_rate_rev_s) || given(spin_tilt_deg) || given(spin_azimuth_deg) ||
         given(marker_noise_mm);
}

void add_throw_options(CLI::App& cmd, ThrowOptions& o) {
  cmd.add_option("--throw", o.preset,
                 "built-in throw preset: built-in (default), paper-body or paper-world (inferred "
                 "from the paper's GF and CP rows in that frame, docs/study.md)");
  cmd.add_option("--spin-rate", o.spin_rate_rev_s, "built-in throw: spin rate, rev/s (1.5)");
  cmd.add_option("--spin-tilt", o.spin_tilt_deg,
                 "built-in throw: spin axis angle from the cylinder axis z, deg (50)");
  cmd.add_option("--spin-azimuth", o.spin_azimuth_deg,
                 "built-in throw: spin axis azimuth from body x, deg (30)");
  cmd.add_option("--duration", o.duration_s, "built-in throw: flight time, s (0.872)");
  cmd.add_option("--marker-noise", o.marker_noise_mm,
                 "built-in throw: marker noise per coordinate, mm (0.1)");
  cmd.add_option("--marker-layout", o.marker_layout, "built-in throw: side-and-end (default) or side");
  cmd.add_option("--axes-sampler", o.axes_sampler,
                 "Monte Carlo axes draws: ball (rotation vector in a ball, default) or cardan "
                 "(three independent angles within the bound)");
}

SyntheticThrowSettings resolve_throw(const ThrowOptions& o) {
  SyntheticThrowSettings s = throw_preset(o.preset);
  apply(o.spin_rate_rev_s, "--spin-rate", 0.05, 20.0, s.spin_rate_rev_s);
  apply(o.spin_tilt_deg, "--spin-tilt", 0.0, 180.0, s.spin_tilt_deg);
  apply(o.spin_azimuth_deg, "--spin-azimuth", -360.0, 360.0, s.spin_azimuth_deg);
  apply(o.duration_s, "--duration", 0.02, 5.0, s.flight_time_s);
  double noise_mm = s.marker_noise_m * 1e3;
  apply(o.marker_noise_mm, "--marker-noise", 0.0, 5.0, noise_mm);
  s.marker_noise_m = noise_mm * 1e-3;
  if (o.marker_layout == "side") {
    s.marker_layout = MarkerLayout::side;
  } else if (o.marker_layout == "side-and-end") {
    s.marker_layout = MarkerLayout::side_and_end;
  } else if (!o.marker_layout.empty()) {
    throw Error("study: --marker-layout must be side-and-end or side, not '" + o.marker_layout + "'");
  }
  return s;
}

AxesSampler resolve_axes_sampler(const ThrowOptions& o) {
  if (o.axes_sampler == "ball") return AxesSampler::ball;
  if (o.axes_sampler == "cardan") return AxesSampler::cardan;
  throw Error("study: --axes-sampler must be ball or cardan, not '" + o.axes_sampler + "'");
}

}  // namespace aloft::host
