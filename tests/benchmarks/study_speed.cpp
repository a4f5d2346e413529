// The default study (the built-in throw: GF and CP, one simulation per sample, and the
// 12 Monte Carlo analyses of 5,000) run twice in one process: one simulation at a time
// (the scalar path, RunSettings::simd_lanes = false) and several at once in SIMD lanes.
// Prints wall and CPU time of each and their ratios, and fails (exit 1) when any RMS DA
// of the two differs by more than 1e-9 degrees.
//
//   aloft_study_speed [--mc N] [--threads T]     the comparison (default N 5000, T 2)
//   aloft_study_speed --growth [--threads T]      time against simulations and flight length
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "study/built_in_study.hpp"
#include "study/paper_cylinder.hpp"
#include "study/study_analyses.hpp"

using namespace aloft::host;

namespace {

struct Timing {
  double wall_s = 0.0;
  double cpu_s = 0.0;
};

double process_cpu_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

Timing run(const BuiltInTrial& trial, std::vector<Analysis>& analyses, unsigned threads, bool lanes) {
  RunSettings settings;
  settings.threads = threads;
  settings.simd_lanes = lanes;
  const auto wall = std::chrono::steady_clock::now();
  const double cpu = process_cpu_s();
  run_analyses(trial.flight, trial.body.inertia, analyses, settings);
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count(),
          process_cpu_s() - cpu};
}

std::vector<Analysis> default_analyses(const BuiltInTrial& trial, std::size_t mc) {
  std::vector<Analysis> out = {model_analysis("GF", trial.body.inertia)};
  for (Analysis& a : paper_monte_carlo_analyses(mc)) out.push_back(a);
  return out;
}

std::size_t simulations(const std::vector<Analysis>& analyses) {
  std::size_t n = 0;
  for (const Analysis& a : analyses) n += a.rms_da_deg[0].size();
  return n;
}

int compare(std::size_t mc, unsigned threads) {
  const BuiltInTrial trial = make_built_in_trial();
  // CP's tensor is a model like GF's; the GF model analysis stands for both here.
  std::vector<Analysis> scalar = default_analyses(trial, mc);
  std::vector<Analysis> lanes = scalar;
  scalar.push_back(model_analysis("GF again", trial.body.inertia));
  lanes.push_back(scalar.back());
  const Timing s = run(trial, scalar, threads, false);
  const Timing l = run(trial, lanes, threads, true);
  double worst = 0.0;
  for (std::size_t a = 0; a < scalar.size(); ++a) {
    for (std::size_t f = 0; f < scalar[a].rms_da_deg.size(); ++f) {
      for (std::size_t i = 0; i < scalar[a].rms_da_deg[f].size(); ++i) {
        worst = std::max(worst, std::abs(scalar[a].rms_da_deg[f][i] - lanes[a].rms_da_deg[f][i]));
      }
    }
  }
  std::printf(
      "study, built-in throw, %zu simulations (2 model analyses, 12 x %zu Monte Carlo), "
      "%u threads\n",
      simulations(scalar), mc, threads);
  std::printf("%-28s %10s %10s\n", "path", "wall (s)", "CPU (s)");
  std::printf("%-28s %10.3f %10.3f\n", "scalar (one at a time)", s.wall_s, s.cpu_s);
  std::printf("%-28s %10.3f %10.3f\n", "SIMD lanes", l.wall_s, l.cpu_s);
  std::printf("CPU ratio scalar / lanes %.2fx, wall ratio %.2fx\n", s.cpu_s / l.cpu_s, s.wall_s / l.wall_s);
  std::printf("largest RMS DA difference %.3g deg (limit 1e-9)\n", worst);
  return worst <= 1e-9 ? 0 : 1;
}

long peak_rss_kib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

int growth(unsigned threads) {
  std::printf("%-34s %12s %10s %10s %14s\n", "run (SIMD lanes)", "simulations", "wall (s)", "CPU (s)",
              "CPU/sim (us)");
  const BuiltInTrial trial = make_built_in_trial();
  for (std::size_t mc : {1000u, 10000u, 100000u, 1000000u}) {
    std::vector<Analysis> one = {monte_carlo_analysis({PerturbationFamily::both, 10.0}, mc)};
    const Timing t = run(trial, one, threads, true);
    std::printf("%-34s %12zu %10.3f %10.3f %14.2f\n", "0.872 s flight, Monte Carlo", mc, t.wall_s, t.cpu_s,
                1e6 * t.cpu_s / static_cast<double>(mc));
  }
  std::printf("peak resident memory after 1M simulations: %ld KiB\n", peak_rss_kib());
  for (double seconds : {0.5, 1.0, 2.0, 4.0}) {
    SyntheticThrowSettings settings;
    settings.flight_time_s = seconds;
    const BuiltInTrial longer = make_built_in_trial(settings);
    std::vector<Analysis> one = {monte_carlo_analysis({PerturbationFamily::both, 10.0}, 10000)};
    const Timing t = run(longer, one, threads, true);
    char label[64];
    std::snprintf(label, sizeof label, "%.1f s flight (%zu samples)", seconds, longer.flight.samples());
    std::printf("%-34s %12d %10.3f %10.3f %14.2f\n", label, 10000, t.wall_s, t.cpu_s,
                1e6 * t.cpu_s / 10000.0);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t mc = paper::kMonteCarloSimulations;
  unsigned threads = 2;
  bool grow = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--mc") == 0 && i + 1 < argc) {
      mc = std::strtoul(argv[++i], nullptr, 10);
    } else if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) {
      threads = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
    } else if (std::strcmp(argv[i], "--growth") == 0) {
      grow = true;
    } else {
      std::fprintf(stderr, "%s: unknown argument %s\n", argv[0], argv[i]);
      return 2;
    }
  }
  return grow ? growth(threads) : compare(mc, threads);
}
