// The analyses of the seed study on one flight, run in parallel:
//  - a model analysis: one full-flight simulation seeded at every sample (873 for the
//    built-in throw) with a fixed tensor (GF, CP, or the body file's tensor);
//  - a Monte Carlo analysis: N simulations, each with its own tensor drawn within a bound
//    around the nominal (study/inertia_perturbation.hpp) and seeded at a sample drawn
//    uniformly from the flight.
// Every Monte Carlo simulation draws from its own random stream, (seed, stream_base,
// simulation index), and writes its result into its own slot, so the results do not
// depend on the number of threads or on scheduling. Simulation i of every Monte Carlo
// analysis gets the same stream: the same seed sample and the same unit perturbation,
// scaled by its bound (common random numbers, study/inertia_perturbation.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "aloft/dynamics/inertia_tensor.hpp"
#include "study/da_frame.hpp"
#include "study/inertia_perturbation.hpp"
#include "study/study_flight.hpp"

namespace aloft::host {

struct Analysis {
  std::string name;  // "GF", "CP", "nominal", "moments 2.5 %", ...
  bool monte_carlo = false;
  InertiaTensor<double> inertia;     // model analyses
  InertiaPerturbation perturbation;  // Monte Carlo analyses
  std::size_t simulations = 0;       // Monte Carlo; a model runs one per seed sample
  // Models: seeded at every seed_stride-th sample (1, the paper's: every sample; the
  // calibration search thins them out for speed).
  std::size_t seed_stride = 1;
  // Filled by run_analyses: one RMS DA per simulation, in each frame (study/da_frame.hpp;
  // the world frame holds NaN for a rate flight).
  std::array<std::vector<double>, kDaFrames> rms_da_deg;

  const std::vector<double>& values(DaFrame frame) const { return rms_da_deg[frame_index(frame)]; }
};

Analysis model_analysis(const std::string& name, const InertiaTensor<double>& inertia);
Analysis monte_carlo_analysis(const InertiaPerturbation& perturbation, std::size_t simulations);

// The 12 Monte Carlo analyses of the seed study: moments, axes and both, each at
// ±2.5, 5, 7.5 and 10 (% or degrees), `simulations` each, axes drawn by `sampler`.
std::vector<Analysis> paper_monte_carlo_analyses(std::size_t simulations,
                                                 AxesSampler sampler = AxesSampler::ball);

struct RunSettings {
  std::uint64_t seed = 1;
  std::uint64_t stream_base = 0;  // separates the streams of several flights
  unsigned threads = 1;
  // Simulations several at once in SIMD lanes (study/full_flight_simulation.hpp); false:
  // one at a time, the scalar path kept for comparison (same numbers within 1e-9 deg).
  bool simd_lanes = true;
  // Called now and then from the calling thread with (done, total) simulations.
  std::function<void(std::size_t, std::size_t)> progress;
};

// Runs every analysis on `flight` (validated first), Monte Carlo draws centred on
// `nominal`. Fills each analysis' rms_da_deg in both frames.
void run_analyses(const StudyFlight& flight, const InertiaTensor<double>& nominal,
                  std::vector<Analysis>& analyses, const RunSettings& settings);

}  // namespace aloft::host
