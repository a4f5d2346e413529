// The noise floor of fast, filtered gyros (issue 31, item 2): generated flights from
// 100 Hz to 8 kHz, with no low-pass or a 2nd-order Butterworth at 20-400 Hz acting on the
// readings (signal and noise), against the truth the generator keeps (the spread of the
// noise as it is in the readings). The estimate must hold within a factor of 2 on every
// flight of the grid, and a flight with noise alone must stay `none`.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <string>
#include <vector>

#include "diagnose/1_input/flight_input.hpp"
#include "diagnose/4_judge/noise_floor.hpp"
#include "diagnose/5_flow/diagnosis.hpp"
#include "generator/body_catalogue.hpp"
#include "generator/flight_generator.hpp"

using namespace aloft::host;
using namespace aloft::host::diagnose;

namespace {

struct GridPoint {
  double rate_hz;
  double cutoff_hz;  // 0: no low-pass
};

// Every rate with no filter and with each cutoff that lies below 0.4 of it (a low-pass at
// or above the Nyquist rate is no low-pass).
std::vector<GridPoint> grid() {
  std::vector<GridPoint> out;
  for (double rate : {100.0, 250.0, 1000.0, 4000.0, 8000.0}) {
    for (double cutoff : {0.0, 20.0, 50.0, 100.0, 200.0, 400.0}) {
      if (cutoff == 0.0 || cutoff < 0.4 * rate) out.push_back({rate, cutoff});
    }
  }
  return out;
}

// Seeds of their own (the withheld sets use 20240515 on): 31000 on, the set the estimate
// was tuned on; 41000 on (ALOFT_NOISE_SEEDS=withheld), a set it was checked on while it
// was tuned; 51000 on (ALOFT_NOISE_SEEDS=fresh), a set measured once, at the end.
std::uint64_t seed_base() {
  const char* set = std::getenv("ALOFT_NOISE_SEEDS");
  if (set != nullptr && std::string(set) == "withheld") return 41000;
  if (set != nullptr && std::string(set) == "fresh") return 51000;
  return 31000;
}

aloft::generator::GeneratedFlight filtered_flight(const GridPoint& p, const std::string& effect, int index) {
  aloft::generator::FlightSpec spec;
  spec.effect = effect;
  spec.body =
      aloft::generator::body_names()[static_cast<std::size_t>(index) % aloft::generator::body_names().size()];
  spec.imu_rate_hz = p.rate_hz;
  spec.gyro_cutoff_hz = p.cutoff_hz;
  return aloft::generator::generate_flight(spec, seed_base() + 97 * static_cast<std::uint64_t>(index));
}

}  // namespace

TEST_CASE("the noise floor holds within x2 from 100 Hz to 8 kHz, filtered or not",
          "[noise_floor][filtered]") {
  int flights = 0, within = 0;
  double worst = 1.0;
  int index = 0;
  for (const GridPoint& p : grid()) {
    for (const std::string effect : {"none", "inertia_moments", "impulse"}) {
      const auto g = filtered_flight(p, effect, index++);
      const Flight flight = flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, "grid");
      const NoiseFloor floor = estimate_noise_floor(flight);
      const Eigen::Vector3d ratio = floor.sigma.cwiseQuotient(g.gyro_noise_in_readings_rad_s);
      const double off = std::max(ratio.maxCoeff(), 1.0 / ratio.minCoeff());
      worst = std::max(worst, off);
      ++flights;
      within += off <= 2.0;
      std::printf(
          "%6.0f Hz, low-pass %4.0f Hz, %-16s %-5s sigma %.5f truth %.5f (x%.2f) correlation %5.1f %s lp "
          "%.0f\n",
          p.rate_hz, p.cutoff_hz, effect.c_str(), g.truth.body.c_str(), floor.sigma.mean(),
          g.gyro_noise_in_readings_rad_s.mean(), off, floor.correlation, floor.method, floor.low_pass_hz);
    }
  }
  std::printf("noise floor within x2 on %d of %d flights; worst x%.2f\n", within, flights, worst);
  // Measured: 66 of 66 on the tuning seeds (worst x1.74: 4 kHz behind 20 Hz, a
  // wrong-moments flight), 66 of 66 on the withheld ones (worst x1.62: 100 Hz behind 20 Hz,
  // a noise-only flight) and 66 of 66 on the fresh set, not tuned on (worst x1.79: 1 kHz
  // behind 20 Hz, a wrong-moments flight). Before the window's response, the finer
  // segments and the outlying segments' removal (noise_spectrum.hpp) it was 65 of 66 on
  // the tuning and withheld seeds (x2.08, x2.12): an impulse flight at 4-8 kHz behind 20 Hz.
  CHECK(within == flights);
  CHECK(worst <= 2.0);
}

TEST_CASE("noise alone behind a gyro's low-pass stays none", "[noise_floor][filtered]") {
  int flights = 0, none = 0, index = 500;
  for (const GridPoint& p : grid()) {
    const auto g = filtered_flight(p, "none", index++);
    Flight flight = flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, "grid");
    const FlightDiagnosis d = diagnose_flight(flight, NominalInertia::of(g.body.inertia));
    const bool ok = d.analysis.verdict.effect == Effect::none;
    ++flights;
    none += ok;
    std::printf("%6.0f Hz, low-pass %4.0f Hz: %s%s (floor %.4f, correlation %.1f, %s)\n", p.rate_hz,
                p.cutoff_hz, effect_name(d.analysis.verdict.effect), ok ? "" : "  WRONG",
                d.noise.sigma.mean(), d.noise.correlation, d.noise.method);
    if (!ok && d.analysis.where.onset_s)
      std::printf("    onset %.3f s of %.3f s\n", *d.analysis.where.onset_s, flight.end_s());
    for (const Candidate& k : d.analysis.candidates)
      if (!ok) std::printf("    %-20s score %12.1f shrink %6.3f\n", effect_name(k.effect), k.score, k.shrink);
  }
  std::printf("noise-only filtered flights: none on %d of %d\n", none, flights);
  CHECK(none == flights);
}
