// `aloft study` (study/study_command.cpp): its options and the outputs it computes in
// memory before it writes any, shared by the command and the Python module (aloft.study).
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "study/paper_cylinder.hpp"
#include "study/recorded_flights.hpp"
#include "study/study_result.hpp"
#include "study/throw_options.hpp"

namespace aloft::host {

struct StudyOptions {
  std::string out_dir = "aloft-study";
  std::uint64_t seed = 1;
  std::size_t mc_samples = paper::kMonteCarloSimulations;
  unsigned threads = 0;        // 0: every core
  std::string frame = "both";  // body, world or both (study/da_frame.hpp)
  RecordingInput recording;
  ThrowOptions throw_options;
  bool calibrate_to_paper = false;
};

// Every option of `aloft study` on `command`.
void add_study_options(CLI::App& command, StudyOptions& options);

// Refuses options that do not go together, or bad values, before any work (Error).
void check_study_options(const StudyOptions& options);

// A study run whole, in memory: results.json's content and the files it goes with.
struct StudyOutputs {
  StudyResult result;
  nlohmann::json results;                                  // results.json
  std::vector<std::pair<std::string, std::string>> files;  // name, content: all the folder's files
  std::string table;                                       // the side-by-side table for stdout
};

// The study the (checked) options ask for, the built-in throw's or a recording's.
StudyOutputs compute_study(const StudyOptions& options);

// Writes the files into `dir`, swapped in whole (common/atomic_folder.hpp).
void write_study_folder(const std::string& dir,
                        const std::vector<std::pair<std::string, std::string>>& files);

}  // namespace aloft::host
