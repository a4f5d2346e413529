#include "study/paper_calibration.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "study/built_in_study.hpp"
#include "study/paper_cylinder.hpp"
#include "study/study_analyses.hpp"

namespace aloft::host {
namespace {

using Clock = std::chrono::steady_clock;

// GF and CP summaries in each frame at one throw.
struct ModelRows {
  std::array<DistributionSummary, kDaFrames> gf, cp;
};

ModelRows evaluate_models(const CalibrationSettings& s, const ThrowParameters& p, std::size_t seed_stride) {
  const BuiltInTrial trial = make_built_in_trial(with_parameters(s.base, p));
  std::vector<Analysis> analyses = {model_analysis("GF", trial.body.inertia),
                                    model_analysis("CP", compound_pendulum_inertia())};
  for (Analysis& a : analyses) a.seed_stride = seed_stride;
  RunSettings run;
  run.threads = s.threads;
  run_analyses(trial.flight, trial.body.inertia, analyses, run);
  ModelRows rows;
  for (DaFrame f : kAllDaFrames) {
    rows.gf[frame_index(f)] = summarise(analyses[0].values(f));
    rows.cp[frame_index(f)] = summarise(analyses[1].values(f));
  }
  return rows;
}

// RMS of the six differences from the paper's GF and CP rows, degrees.
double rms_difference(const ModelRows& rows, DaFrame frame) {
  double sum = 0.0;
  const auto add = [&](const DistributionSummary& s, const paper::PublishedRow& row) {
    sum += (s.p10 - row.p10) * (s.p10 - row.p10) + (s.median - row.median) * (s.median - row.median) +
           (s.p90 - row.p90) * (s.p90 - row.p90);
  };
  add(rows.gf[frame_index(frame)], paper::kGeometricFormulae);
  add(rows.cp[frame_index(frame)], paper::kCompoundPendulum);
  return std::sqrt(sum / 6.0);
}

// The searched range of each parameter, and the compass search's first and last steps.
struct Range {
  double low, high, first_step, last_step;
};
constexpr std::array<Range, 4> kRanges = {{
    {0.3, 4.0, 0.25, 0.02},     // spin rate, rev/s
    {0.0, 90.0, 8.0, 0.5},      // tilt from z, deg (the cylinder is symmetric about its mid-plane)
    {0.0, 90.0, 15.0, 1.0},     // azimuth from x, deg (CP is symmetric about x and y)
    {0.005, 0.3, 0.02, 0.002},  // marker noise, mm
}};

double& parameter(ThrowParameters& p, std::size_t i) {
  switch (i) {
    case 0: return p.spin_rate_rev_s;
    case 1: return p.spin_tilt_deg;
    case 2: return p.spin_azimuth_deg;
    default: return p.marker_noise_mm;
  }
}

struct Scored {
  ThrowParameters p;
  double score = 0.0;
};

std::vector<ThrowParameters> coarse_grid() {
  std::vector<ThrowParameters> grid;
  for (double rate : {0.5, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0}) {
    for (double tilt : {10.0, 25.0, 40.0, 55.0, 70.0, 80.0, 90.0}) {
      for (double azimuth : {0.0, 30.0, 60.0, 90.0}) {
        for (double noise : {0.03, 0.05, 0.07, 0.1, 0.14}) {
          grid.push_back({rate, tilt, azimuth, noise});
        }
      }
    }
  }
  return grid;
}

// Compass search from `start`, models seeded at every 2nd sample. Counts evaluations.
Scored refine(const CalibrationSettings& s, DaFrame frame, Scored best, std::size_t& evaluations,
              const std::function<void()>& tick) {
  constexpr std::size_t kStride = 2;
  const std::size_t kBudget = s.refine_budget;
  best.score = rms_difference(evaluate_models(s, best.p, kStride), frame);
  std::array<double, 4> step;
  for (std::size_t i = 0; i < 4; ++i) step[i] = kRanges[i].first_step;
  for (std::size_t used = 1; used < kBudget;) {
    bool improved = false;
    for (std::size_t i = 0; i < 4 && !improved && used < kBudget; ++i) {
      for (double sign : {1.0, -1.0}) {
        Scored trial = best;
        double& v = parameter(trial.p, i);
        v = std::clamp(v + sign * step[i], kRanges[i].low, kRanges[i].high);
        if (v == parameter(best.p, i)) continue;
        trial.score = rms_difference(evaluate_models(s, trial.p, kStride), frame);
        ++used;
        ++evaluations;
        tick();
        if (trial.score < best.score) {
          best = trial;
          improved = true;
          break;
        }
      }
    }
    if (improved) continue;
    bool finer = false;
    for (std::size_t i = 0; i < 4; ++i) {
      if (step[i] / 2.0 >= kRanges[i].last_step) {
        step[i] /= 2.0;
        finer = true;
      }
    }
    if (!finer) break;
  }
  return best;
}

// GF and CP at every sample, then the three ±10 Monte Carlo rows, at the throw found.
std::vector<PredictedRow> predicted_rows(const CalibrationSettings& s, const ThrowParameters& p,
                                         DaFrame frame) {
  const BuiltInTrial trial = make_built_in_trial(with_parameters(s.base, p));
  std::vector<Analysis> analyses = {model_analysis("GF", trial.body.inertia),
                                    model_analysis("CP", compound_pendulum_inertia())};
  for (PerturbationFamily family :
       {PerturbationFamily::moments, PerturbationFamily::axes, PerturbationFamily::both}) {
    analyses.push_back(monte_carlo_analysis({family, 10.0, s.sampler}, s.mc_samples));
  }
  RunSettings run;
  run.seed = s.seed;
  run.threads = s.threads;
  run_analyses(trial.flight, trial.body.inertia, analyses, run);
  std::vector<PredictedRow> rows;
  for (const Analysis& a : analyses) {
    rows.push_back({a.name, summarise(a.values(frame)), !a.monte_carlo});
  }
  return rows;
}

}  // namespace

SyntheticThrowSettings with_parameters(SyntheticThrowSettings base, const ThrowParameters& p) {
  base.spin_rate_rev_s = p.spin_rate_rev_s;
  base.spin_tilt_deg = p.spin_tilt_deg;
  base.spin_azimuth_deg = p.spin_azimuth_deg;
  base.marker_noise_m = p.marker_noise_mm * 1e-3;
  return base;
}

CalibrationResult calibrate_to_paper(const CalibrationSettings& s, const std::vector<DaFrame>& frames) {
  const Clock::time_point start = Clock::now();
  const auto report = [&](const std::string& phase, std::size_t done, std::size_t total) {
    if (s.progress) s.progress(phase, done, total);
  };
  CalibrationResult result;

  // 1. The grid, scored in every frame at once.
  const std::vector<ThrowParameters> grid = s.grid.empty() ? coarse_grid() : s.grid;
  result.grid_points = grid.size();
  std::vector<std::vector<Scored>> scored(kDaFrames);
  for (std::size_t g = 0; g < grid.size(); ++g) {
    const ModelRows rows = evaluate_models(s, grid[g], 8);
    for (DaFrame f : kAllDaFrames) scored[frame_index(f)].push_back({grid[g], rms_difference(rows, f)});
    report("grid", g + 1, grid.size());
  }

  for (DaFrame frame : frames) {
    // 2. Refine the best three grid points.
    std::vector<Scored>& candidates = scored[frame_index(frame)];
    const std::size_t starts = std::max<std::size_t>(1, std::min(s.refine_starts, candidates.size()));
    std::partial_sort(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(starts),
                      candidates.end(), [](const Scored& a, const Scored& b) { return a.score < b.score; });
    FrameCalibration fc;
    fc.frame = frame;
    fc.evaluations = grid.size();
    const std::string phase = std::string("refine ") + frame_name(frame);
    std::size_t refined = 0;
    Scored best;
    for (std::size_t c = 0; c < starts; ++c) {
      const Scored found = refine(s, frame, candidates[c], fc.evaluations,
                                  [&] { report(phase, ++refined, starts * s.refine_budget); });
      if (c == 0 || found.score < best.score) best = found;
    }
    // 3. The throw found, every sample, and the rows it predicts.
    fc.throw_found = best.p;
    fc.search_rms_diff_deg = rms_difference(evaluate_models(s, best.p, 1), frame);
    report(std::string("predict ") + frame_name(frame), 0, 1);
    fc.rows = predicted_rows(s, best.p, frame);
    report(std::string("predict ") + frame_name(frame), 1, 1);
    result.frames.push_back(fc);
  }
  result.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace aloft::host
