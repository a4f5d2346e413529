#include "study/study_analyses.hpp"

#include <boost/random/uniform_int_distribution.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <mutex>
#include <thread>

#include "study/full_flight_simulation.hpp"
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
    std::snprintf(name, sizeof name, "%s %g %s", family_name(perturbation.family),
                  perturbation.bound, family_unit(perturbation.family));
  }
  a.name = name;
  a.monte_carlo = true;
  a.perturbation = perturbation;
  a.simulations = simulations;
  return a;
}

std::vector<Analysis> paper_monte_carlo_analyses(std::size_t simulations) {
  std::vector<Analysis> out;
  for (PerturbationFamily family :
       {PerturbationFamily::moments, PerturbationFamily::axes, PerturbationFamily::both}) {
    for (double bound : paper::kBounds) {
      out.push_back(monte_carlo_analysis({family, bound}, simulations));
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
    if (!an.monte_carlo) an.simulations = n;
    for (std::vector<double>& v : an.rms_da_deg) v.assign(an.simulations, 0.0);
    first[a + 1] = first[a] + an.simulations;
  }
  const std::size_t total = first.back();

  const auto store = [](Analysis& an, std::size_t i, const RmsDaByFrame& rms) {
    for (std::size_t f = 0; f < kDaFrames; ++f) an.rms_da_deg[f][i] = rms[f];
  };
  const auto run_one = [&](std::size_t flat) {
    const std::size_t a = static_cast<std::size_t>(
        std::upper_bound(first.begin(), first.end(), flat) - first.begin() - 1);
    Analysis& an = analyses[a];
    const std::size_t i = flat - first[a];
    if (!an.monte_carlo) {
      store(an, i, full_flight_rms_da_deg(flight, an.inertia, i));
      return;
    }
    SimulationRandom random(settings.seed, settings.stream_base, i);  // paired across analyses
    boost::random::uniform_int_distribution<std::size_t> sample(0, n - 1);
    const std::size_t k = sample(random);
    const InertiaTensor<double> inertia = draw_perturbed_inertia(nominal, an.perturbation, random);
    store(an, i, full_flight_rms_da_deg(flight, inertia, k));
  };

  constexpr std::size_t kChunk = 64;
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto worker = [&] {
    try {
      for (;;) {
        const std::size_t begin = next.fetch_add(kChunk);
        if (begin >= total) return;
        const std::size_t end = std::min(total, begin + kChunk);
        for (std::size_t f = begin; f < end; ++f) run_one(f);
        done.fetch_add(end - begin);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(failure_mutex);
      if (!failure) failure = std::current_exception();
      next.store(total);
    }
  };

  const unsigned threads = std::max(1u, settings.threads);
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
  if (settings.progress) {
    // The calling thread reports progress while the workers run, then joins the work.
    std::thread last(worker);
    while (done.load() < total && next.load() < total) {
      settings.progress(done.load(), total);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    last.join();
  } else {
    worker();
  }
  for (std::thread& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
  if (settings.progress) settings.progress(total, total);
}

}  // namespace aloft::host
