// Everything one `aloft study` run produced, as the outputs (results.json, rms_da.csv,
// experiment.csv, the figure, the table) read it.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "study/da_frame.hpp"
#include "study/study_analyses.hpp"
#include "study/study_flight.hpp"

namespace aloft::host {

struct FlightStudy {
  StudyFlight flight;
  std::vector<Analysis> analyses;  // models first, then the Monte Carlo analyses
};

struct StudyResult {
  bool built_in = false;  // the paper's cylinder on the built-in throw
  std::string input;      // what was studied, for people
  nlohmann::json trial;   // how the trial was made or read (more keys in results.json)
  std::vector<FlightStudy> flights;
  std::uint64_t seed = 0;
  unsigned threads = 1;
  std::size_t mc_samples = 0;
  AxesSampler axes_sampler = AxesSampler::ball;
  // The frames reported (--frame), the first one also under SPEC §5's top-level keys.
  std::vector<DaFrame> frames = {DaFrame::body, DaFrame::world};
  std::vector<std::pair<std::string, double>> phase_time_s;  // where the time went
  double wall_time_s = 0.0;
};

// Every simulation's RMS DA in `frame` of the analysis named `name`, pooled over all flights.
std::vector<double> pooled_rms_da(const StudyResult& result, const std::string& name, DaFrame frame);

}  // namespace aloft::host
