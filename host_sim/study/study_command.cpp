// `aloft study` (SPEC §5): the seed paper's cylinder study on the built-in throw, or the
// same analyses on a recording. Everything is computed in memory first; only then are
// the files written, into a new folder swapped in whole (common/atomic_folder.hpp), so
// the output folder is all old or all new, even after a kill -9.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <iostream>
#include <thread>

#include <unistd.h>

#include "common/json_text.hpp"
#include "common/atomic_file.hpp"
#include "common/atomic_folder.hpp"
#include "common/commands.hpp"
#include "common/option_checks.hpp"
#include "readers/pose_naming_options.hpp"
#include "study/boxplot_figure.hpp"
#include "study/built_in_study.hpp"
#include "study/paper_calibration_report.hpp"
#include "study/paper_cylinder.hpp"
#include "study/recorded_flights.hpp"
#include "study/study_command.hpp"
#include "study/study_outputs.hpp"
#include "study/throw_options.hpp"

namespace aloft::host {
namespace {

// What the nominal figure of a recording measures, beside `aloft diagnose`'s baseline for
// the same data (docs/study.md, "Study and diagnose on the same data"): different questions.
constexpr const char* kNominalMeasures =
    "one simulation seeded from each measured sample, run over the whole flight (the paper's "
    "measure); aloft diagnose fits the start to the whole flight instead, the model's best case";

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

void check_study_options(const StudyOptions& o) {
  const RecordingInput& r = o.recording;
  const int sources = !r.markers_path.empty() + !r.poses_path.empty() + !r.imu_path.empty();
  if (r.body_path.empty() && sources > 0) {
    throw Error("study: --markers, --poses and --imu need --body BODY.json");
  }
  if (!r.body_path.empty() && sources != 1) {
    throw Error("study: --body needs exactly one of --markers, --poses or --imu");
  }
  if (!r.segments_path.empty() && r.imu_path.empty()) {
    throw Error("study: --segments goes with --imu");
  }
  if (o.mc_samples < 1) throw Error("study: --mc-samples must be at least 1");
  if (o.frame != "body" && o.frame != "world" && o.frame != "both") {
    throw Error("study: --frame must be body, world or both, not '" + o.frame + "'");
  }
  if (!r.body_path.empty() && o.throw_options.throw_given()) {
    throw Error(
        "study: --throw, --spin-*, --duration and --marker-* shape the built-in "
        "throw; they do not apply to a recording");
  }
  if (o.calibrate_to_paper && (!r.body_path.empty() || o.throw_options.searched_given())) {
    throw Error(
        "study: --calibrate-to-paper searches the built-in throw's spin and marker "
        "noise; it takes no recording, --throw, --spin-* or --marker-noise");
  }
  resolve_throw(o.throw_options);  // refuses bad values before any work
  resolve_axes_sampler(o.throw_options);
  if (o.frame == "world" && !r.imu_path.empty()) {
    throw Error("study: --frame world needs orientations; an IMU recording has only body rates");
  }
}

namespace {

// The frames to report: an IMU recording has no world frame, so "both" is body there.
std::vector<DaFrame> frames_to_report(const StudyOptions& o) {
  if (o.frame == "body" || !o.recording.imu_path.empty()) return {DaFrame::body};
  if (o.frame == "world") return {DaFrame::world};
  return {DaFrame::body, DaFrame::world};
}

// "\rstudy: 12,345 / 61,746 simulations (20 %)" on a terminal, nothing otherwise.
std::function<void(std::size_t, std::size_t)> terminal_progress(const std::string& label) {
  if (!::isatty(STDERR_FILENO)) return {};
  return [label](std::size_t done, std::size_t total) {
    std::fprintf(stderr, "\rstudy: %s: %zu / %zu simulations (%3.0f %%)", label.c_str(), done, total,
                 100.0 * static_cast<double>(done) / static_cast<double>(total));
    if (done == total) std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
  };
}

StudyResult run_study(const StudyOptions& o) {
  const Clock::time_point start = Clock::now();
  StudyResult result;
  result.seed = o.seed;
  result.mc_samples = o.mc_samples;
  result.frames = frames_to_report(o);
  result.threads = o.threads > 0 ? o.threads : std::max(1u, std::thread::hardware_concurrency());

  // The trial and the tensors the analyses use.
  InertiaTensor<double> nominal;
  std::vector<Analysis> models;
  if (o.recording.body_path.empty()) {
    BuiltInTrial trial = make_built_in_trial(resolve_throw(o.throw_options));
    trial.description["preset"] = o.throw_options.preset;
    result.built_in = true;
    result.input = "built-in throw of the paper's cylinder";
    result.trial = trial.description;
    nominal = trial.body.inertia;
    models = {model_analysis("GF", nominal), model_analysis("CP", compound_pendulum_inertia())};
    result.flights.push_back({std::move(trial.flight), {}});
  } else {
    RecordedTrial trial = load_recorded_trial(o.recording);
    result.input = trial.body.name.empty() ? o.recording.body_path : trial.body.name;
    result.trial = trial.description;
    result.trial["nominal_measures"] = kNominalMeasures;
    nominal = trial.body.inertia;
    models = {model_analysis("nominal", nominal)};
    for (StudyFlight& f : trial.flights) result.flights.push_back({std::move(f), {}});
  }
  result.phase_time_s.emplace_back("trial", seconds_since(start));

  // The simulations: every flight, models then the 12 Monte Carlo analyses.
  const AxesSampler sampler = resolve_axes_sampler(o.throw_options);
  result.axes_sampler = sampler;
  const Clock::time_point simulations_start = Clock::now();
  for (std::size_t i = 0; i < result.flights.size(); ++i) {
    FlightStudy& fs = result.flights[i];
    fs.analyses = models;
    for (Analysis& a : paper_monte_carlo_analyses(o.mc_samples, sampler)) fs.analyses.push_back(a);
    RunSettings run;
    run.seed = o.seed;
    run.stream_base = 64 * i;
    run.threads = result.threads;
    run.progress = terminal_progress(fs.flight.name);
    run_analyses(fs.flight, nominal, fs.analyses, run);
  }
  result.phase_time_s.emplace_back("simulations", seconds_since(simulations_start));
  return result;
}

}  // namespace

void write_study_folder(const std::string& dir,
                        const std::vector<std::pair<std::string, std::string>>& files) {
  replace_folder_atomically(dir, [&](const std::string& fresh) {
    for (const auto& file : files) {
      // Not a structured binding: a lambda capturing one is C++20, and clang refuses it.
      const std::string& content = file.second;
      const std::string path = (std::filesystem::path(fresh) / file.first).string();
      write_file_atomically(path, [&](std::ostream& out) { out << content; });
    }
  });
}

namespace {

// "study: calibrate: grid 120 / 1120" now and then on stderr: the search takes minutes.
std::function<void(const std::string&, std::size_t, std::size_t)> calibration_progress() {
  const bool terminal = ::isatty(STDERR_FILENO);
  return [terminal](const std::string& phase, std::size_t done, std::size_t total) {
    if (terminal) {
      std::fprintf(stderr, "\rstudy: calibrate: %s %zu / %zu\033[K", phase.c_str(), done, total);
    } else if (done == total || done % 100 == 0) {
      std::fprintf(stderr, "study: calibrate: %s %zu / %zu\n", phase.c_str(), done, total);
    }
    std::fflush(stderr);
  };
}

void calibrate(const StudyOptions& o) {
  CalibrationSettings s;
  s.base = resolve_throw(o.throw_options);
  s.sampler = resolve_axes_sampler(o.throw_options);
  s.mc_samples = o.mc_samples;
  s.seed = o.seed;
  s.threads = o.threads > 0 ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  s.progress = calibration_progress();
  const CalibrationResult result = calibrate_to_paper(s, frames_to_report(o));
  if (::isatty(STDERR_FILENO)) std::fputs("\r\033[K", stderr);
  write_study_folder(o.out_dir, {{"calibration.json", json_text(calibration_json(result, s)) + "\n"}});
  std::fputs(calibration_table(result).c_str(), stdout);
  std::printf("wall time %.1f s on %u thread%s; wrote %s/calibration.json\n", result.wall_time_s, s.threads,
              s.threads == 1 ? "" : "s", o.out_dir.c_str());
}

void study(const StudyOptions& o) {
  check_study_options(o);
  clean_after_killed_runs(o.out_dir);
  if (o.calibrate_to_paper) return calibrate(o);
  const StudyOutputs outputs = compute_study(o);
  const StudyResult& result = outputs.result;
  write_study_folder(o.out_dir, outputs.files);

  std::printf("aloft study: %s, %zu flight%s, seed %llu, %u thread%s\n", result.input.c_str(),
              result.flights.size(), result.flights.size() == 1 ? "" : "s",
              static_cast<unsigned long long>(result.seed), result.threads, result.threads == 1 ? "" : "s");
  std::fputs(outputs.table.c_str(), stdout);
  if (!result.built_in) std::printf("nominal: %s\n", kNominalMeasures);
  std::printf("wall time %.2f s (", result.wall_time_s);
  for (std::size_t i = 0; i < result.phase_time_s.size(); ++i) {
    std::printf("%s%s %.2f s", i ? ", " : "", result.phase_time_s[i].first.c_str(),
                result.phase_time_s[i].second);
  }
  std::printf("); wrote %s/{results.json, rms_da.csv, experiment.csv, figure.svg, figure.png}\n",
              o.out_dir.c_str());
}

}  // namespace

StudyOutputs compute_study(const StudyOptions& o) {
  const Clock::time_point start = Clock::now();
  StudyOutputs outputs;
  StudyResult& result = outputs.result;
  result = run_study(o);

  const Clock::time_point outputs_start = Clock::now();
  const FigureFiles figure = render_study_figure(result);
  const std::string experiment = experiment_csv(result);
  const std::string rms_da = rms_da_csv(result);
  outputs.table = comparison_table(result);
  result.phase_time_s.emplace_back("outputs", seconds_since(outputs_start));
  result.wall_time_s = seconds_since(start);
  outputs.results = results_json(result);
  outputs.files = {{"experiment.csv", experiment},
                   {"rms_da.csv", rms_da},
                   {"figure.svg", figure.svg},
                   {"figure.png", figure.png},
                   {"results.json", json_text(outputs.results) + "\n"}};
  return outputs;
}

void add_study_options(CLI::App& command, StudyOptions& options) {
  CLI::App* cmd = &command;
  cmd->add_option("--out", options.out_dir, "output folder (default aloft-study)")->check(output_folder());
  cmd->add_option("--seed", options.seed, "seed of the Monte Carlo draws (default 1)")->check(whole_number());
  cmd->add_option("--mc-samples", options.mc_samples,
                  "simulations per Monte Carlo analysis and flight (default 5000)")
      ->check(whole_number());
  cmd->add_option("--threads", options.threads, "worker threads (default: every core)")
      ->check(whole_number());
  cmd->add_option("--frame", options.frame,
                  "axes in which simulated and measured omega are compared: body, world or "
                  "both (default both; IMU input: body only)");
  cmd->add_option("--body", options.recording.body_path,
                  "body file of a recording (JSON: docs/file-formats.md)");
  cmd->add_option("--markers", options.recording.markers_path, "marker trajectories (.trc, .c3d)");
  cmd->add_option("--poses", options.recording.poses_path, "poses (.mot, .sto, pose .csv)");
  add_pose_naming_options(*cmd, options.recording.pose_naming);
  cmd->add_option("--imu", options.recording.imu_path, "IMU log (plain or phyphox .csv)");
  cmd->add_option("--segments", options.recording.segments_path, "flights within the IMU log");
  add_imu_unit_options(*cmd, options.recording.imu_units);
  add_throw_options(*cmd, options.throw_options);
  cmd->add_flag("--calibrate-to-paper", options.calibrate_to_paper,
                "search the throw (spin rate, axis, marker noise) that matches the paper's GF "
                "and CP rows, per frame, and predict its Monte Carlo rows (docs/study.md); writes "
                "calibration.json");
}

void add_study_command(CLI::App& app) {
  auto options = std::make_shared<StudyOptions>();
  auto* cmd =
      app.add_subcommand("study",
                         "the seed paper's inertia study: GF vs CP and 12 Monte Carlo analyses, on the "
                         "built-in throw or on a recording");
  add_study_options(*cmd, *options);
  cmd->callback([options] { study(*options); });
}

}  // namespace aloft::host
