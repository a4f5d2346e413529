#include "study/study_analyses.hpp"

#include <boost/random/uniform_int_distribution.hpp>

#include <algorithm>
#include <cstdio>

#include "common/parallel_for.hpp"
#include "study/full_flight_simulation.hpp"
#include "study/full_flight_wide_lanes.hpp"
#include "study/paper_cylinder.hpp"

namespace aloft::host {

Analysis model_analysis(const std::string& name, const InertiaTensor<double>& inertia) {
  Analysis a;
  a.name = name;
  a.inertia = inertia;
  return a;
}

Analysis monte_carlo_analysis(const InertiaPerturbation& perturbation, std::size_t simulations) {
  Analysis a;
  char name[64];
  if (perturbation.family == PerturbationFamily::both) {
    std::snprintf(name, sizeof name, "both %g %% + %g deg", perturbation.bound, perturbation.bound);
  } else {
    std::snprintf(name, sizeof name, "%s %g %s", family_name(perturbation.family), perturbation.bound,
                  family_unit(perturbation.family));
  }
  a.name = name;
  a.monte_carlo = true;
  a.perturbation = perturbation;
  a.simulations = simulations;
  return a;
}

std::vector<Analysis> paper_monte_carlo_analyses(std::size_t simulations, AxesSampler sampler) {
  std::vector<Analysis> out;
  for (PerturbationFamily family :
       {PerturbationFamily::moments, PerturbationFamily::axes, PerturbationFamily::both}) {
    for (double bound : paper::kBounds) {
      out.push_back(monte_carlo_analysis({family, bound, sampler}, simulations));
    }
  }
  return out;
}

void run_analyses(const StudyFlight& flight, const InertiaTensor<double>& nominal,
                  std::vector<Analysis>& analyses, const RunSettings& settings) {
  validate_study_flight(flight);
  const std::size_t n = flight.samples();
  // One flat index over every simulation of every analysis.
  std::vector<std::size_t> first(analyses.size() + 1, 0);
  for (std::size_t a = 0; a < analyses.size(); ++a) {
    Analysis& an = analyses[a];
    if (!an.monte_carlo) an.simulations = (n + an.seed_stride - 1) / an.seed_stride;
    for (std::vector<double>& v : an.rms_da_deg) v.assign(an.simulations, 0.0);
    first[a + 1] = first[a] + an.simulations;
  }
  const std::size_t total = first.back();

  const auto store = [](Analysis& an, std::size_t i, const RmsDaByFrame& rms) {
    for (std::size_t f = 0; f < kDaFrames; ++f) an.rms_da_deg[f][i] = rms[f];
  };
  // Simulation `flat`: its analysis, index in it, seed sample and tensor.
  struct Simulation {
    Analysis* analysis;
    std::size_t index;
    std::size_t seed_sample;
    InertiaTensor<double> inertia;
  };
  const auto simulation = [&](std::size_t flat) {
    const std::size_t a =
        static_cast<std::size_t>(std::upper_bound(first.begin(), first.end(), flat) - first.begin() - 1);
    Analysis& an = analyses[a];
    const std::size_t i = flat - first[a];
    if (!an.monte_carlo) return Simulation{&an, i, i * an.seed_stride, an.inertia};
    SimulationRandom random(settings.seed, settings.stream_base, i);  // paired across analyses
    boost::random::uniform_int_distribution<std::size_t> sample(0, n - 1);
    const std::size_t k = sample(random);
    return Simulation{&an, i, k, draw_perturbed_inertia(nominal, an.perturbation, random)};
  };
  const LaneFlight lane_flight(flight);
  const std::size_t lanes = settings.simd_lanes ? simulation_lanes() : 1;
  // Simulations [begin, end), `lanes` at a time.
  const auto run_range = [&](std::size_t begin, std::size_t end) {
    for (std::size_t group = begin; group < end; group += lanes) {
      const std::size_t count = std::min(lanes, end - group);
      Simulation sims[kFullFlightLanesAvx512];
      FlightSimulation<double> lane_sims[kFullFlightLanesAvx512];
      RmsDaByFrame rms[kFullFlightLanesAvx512];
      for (std::size_t l = 0; l < count; ++l) {
        sims[l] = simulation(group + l);
        lane_sims[l] = flight_simulation(sims[l].inertia, sims[l].seed_sample);
      }
      if (settings.simd_lanes) {
        full_flight_rms_da_deg_lanes(lane_flight, lane_sims, count, rms);
      } else {
        rms[0] = full_flight_rms_da_deg(flight, sims[0].inertia, sims[0].seed_sample);
      }
      for (std::size_t l = 0; l < count; ++l) store(*sims[l].analysis, sims[l].index, rms[l]);
    }
  };

  // Chunks of simulations keep the hand-out cheap next to the work (~100 us each).
  constexpr std::size_t kChunk = 64;
  const std::size_t chunks = (total + kChunk - 1) / kChunk;
  ParallelProgress progress;
  if (settings.progress) {
    progress.report = [&](std::size_t done, std::size_t) {
      settings.progress(std::min(total, done * kChunk), total);
    };
  }
  parallel_for(
      chunks, std::max(1u, settings.threads),
      [&](std::size_t c) { run_range(c * kChunk, std::min(total, (c + 1) * kChunk)); }, progress);
}

}  // namespace aloft::host
