// `aloft study --calibrate-to-paper`: which throw makes the built-in study give the
// paper's GF and CP rows? The paper says neither the spin rate, nor its axis, nor the
// marker noise, and these decide the numbers. The search matches the paper's GF and CP
// rows only (p10, median, p90: six numbers) in each frame, then runs the three Monte
// Carlo families at ±10 at the throw found: those rows were not used to find the throw,
// so set beside the paper's they are a prediction, not a fit.
//
// The search, per frame, minimises the RMS of the six differences (degrees) over spin
// rate, spin axis (tilt from z, azimuth from x) and marker noise:
//  1. a coarse grid over the whole range, the models seeded at every 8th sample (both
//     frames come out of each simulation, so one grid serves both);
//  2. a compass search (each parameter up and down, steps halved when nothing
//     improves) from the best three grid points, seeded at every 2nd sample;
//  3. the best throw evaluated with every sample as seed, then the Monte Carlo rows.
// The flight time (0.872 s, the paper's), the marker layout and the axes sampler stay as
// given. Each evaluation runs on `threads` threads (study/study_analyses.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "study/da_frame.hpp"
#include "study/inertia_perturbation.hpp"
#include "study/percentiles.hpp"
#include "study/synthetic_throw.hpp"

namespace aloft::host {

// The searched parameters of a throw.
struct ThrowParameters {
  double spin_rate_rev_s = 0.0, spin_tilt_deg = 0.0, spin_azimuth_deg = 0.0, marker_noise_mm = 0.0;
};

struct CalibrationSettings {
  SyntheticThrowSettings base;  // everything not searched
  AxesSampler sampler = AxesSampler::ball;
  std::size_t mc_samples = 5000;
  std::uint64_t seed = 1;
  unsigned threads = 1;
  // The search's size: the grid (empty: the built-in 1,120 points), how many of its best
  // points are refined, and the evaluations each refinement may take.
  std::vector<ThrowParameters> grid;
  std::size_t refine_starts = 3;
  std::size_t refine_budget = 60;
  // (phase, done, total) now and then; phases "grid", "refine body", ...
  std::function<void(const std::string&, std::size_t, std::size_t)> progress;
};

// One named row of the study: its RMS DA summary, and the paper's where it has one.
struct PredictedRow {
  std::string name;  // "GF", "CP", "moments 10 %", "axes 10 deg", "both 10 % + 10 deg"
  DistributionSummary summary;
  bool used_in_search = false;  // GF and CP: the rows the throw was fitted to
};

struct FrameCalibration {
  DaFrame frame = DaFrame::body;
  ThrowParameters throw_found;
  double search_rms_diff_deg = 0.0;  // RMS of the six GF/CP differences, every sample
  std::size_t evaluations = 0;
  std::vector<PredictedRow> rows;  // GF, CP, then moments, axes, both at ±10
};

struct CalibrationResult {
  std::vector<FrameCalibration> frames;
  std::size_t grid_points = 0;
  double wall_time_s = 0.0;
};

SyntheticThrowSettings with_parameters(SyntheticThrowSettings base, const ThrowParameters& p);

CalibrationResult calibrate_to_paper(const CalibrationSettings& settings, const std::vector<DaFrame>& frames);

}  // namespace aloft::host
