// Flights that share one value agree within their errors behind any common gyro filter:
// the between-flight scatter (4_judge/between_flight_scatter.hpp), a chi-square per degree
// of freedom of the flights' own fits about their weighted mean, is 1 with a spread of
// sqrt(2 / dof) when each fit counts independent samples, and as many times that as the
// readings per independent sample where a fit counts readings (25 behind a first-order
// 50 Hz low-pass at 4 kHz). Generated sessions of five flights sharing one rotor
// (internal_momentum, the effect the rule rules out when its flights disagree), from
// 100 Hz to 8 kHz, with no low-pass, a second-order Butterworth or a flight controller's
// first-order PT1 at 20-400 Hz, quantised to 1/16.4 deg/s as a flight controller logs.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "diagnose/1_input/flight_input.hpp"
#include "diagnose/3_fit/effect_fit.hpp"
#include "diagnose/4_judge/between_flight_scatter.hpp"
#include "diagnose/4_judge/noise_floor.hpp"
#include "generator/body_catalogue.hpp"
#include "generator/flight_generator.hpp"

using namespace aloft::host;
using namespace aloft::host::diagnose;

namespace {

struct GridPoint {
  double rate_hz;
  int order;  // 0: no low-pass; 1: PT1; 2: Butterworth
  double cutoff_hz;
};

// Flight-controller rates and a phone's, each with no low-pass and with both shapes at
// the cutoffs that lie below 0.4 of the rate. `near_motion`: the PT1s at 20 Hz, printed
// but not held to the bar. Their knee lies a few times above a tumble's frequencies: at
// 1-8 kHz the PT1's phase distortion (a first-order low-pass is a delay plus (RC^2 / 2) w''
// to second order, a Butterworth a delay alone) bends the readings beyond the noise, so a
// flight's fit leaves a misfit the model does not know of; at 100 Hz the knee lies at the
// motion band's edge, where the noise floor does not take a first-order shape
// (noise_floor.cpp, fitted_low_pass).
std::vector<GridPoint> grid(bool small, bool near_motion) {
  if (small) return near_motion ? std::vector<GridPoint>{} : std::vector<GridPoint>{{1000.0, 1, 50.0}};
  std::vector<GridPoint> out;
  for (double rate : {100.0, 1000.0, 4000.0, 8000.0}) {
    if (!near_motion) out.push_back({rate, 0, 0.0});
    for (int order : {1, 2}) {
      for (double cutoff : {20.0, 50.0, 100.0, 400.0}) {
        if (near_motion != (order == 1 && cutoff < 50.0)) continue;
        if (cutoff < 0.4 * rate) out.push_back({rate, order, cutoff});
      }
    }
  }
  return out;
}

// Seeds of their own: 61000 on, the set the estimate was tuned on; 71000 on
// (ALOFT_SCATTER_SEEDS=fresh), measured once the rule was set.
std::uint64_t seed_base() {
  const char* set = std::getenv("ALOFT_SCATTER_SEEDS");
  return set != nullptr && std::string(set) == "fresh" ? 71000 : 61000;
}

constexpr double kFlightControllerStep = 3.14159265358979323846 / 180.0 / 16.4;  // rad/s
constexpr int kFlights = 5;

struct SessionScatter {
  double scatter = 0.0;
  double correlation = 0.0, true_correlation = 0.0;
};

SessionScatter session_scatter(const GridPoint& p, int index) {
  const std::uint64_t seed = seed_base() + 131 * static_cast<std::uint64_t>(index);
  const std::string body =
      aloft::generator::body_names()[static_cast<std::size_t>(index) % aloft::generator::body_names().size()];
  std::vector<Flight> flights;
  std::vector<Analysis> own(kFlights);
  SessionScatter out;
  flights.reserve(kFlights);
  for (int f = 0; f < kFlights; ++f) {
    aloft::generator::FlightSpec spec;
    spec.effect = "internal_momentum";
    spec.body = body;
    spec.imu_rate_hz = p.rate_hz;
    spec.gyro_cutoff_hz = p.cutoff_hz;
    spec.gyro_filter_order = p.order == 0 ? 2 : p.order;
    spec.gyro_quantum_rad_s = kFlightControllerStep;
    spec.throw_seed = seed + 7 + static_cast<std::uint64_t>(f);
    const auto g = aloft::generator::generate_flight(spec, seed);
    flights.push_back(flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, "f" + std::to_string(f)));
    const NominalInertia nominal = NominalInertia::of(g.body.inertia);
    const NoiseFloor noise = estimate_noise_floor(flights.back());
    const FlightData data{&flights.back(), SampleMask(flights.back().size(), 1),
                          noise.weighting_sigma().cwiseInverse()};
    const EffectFit none = fit_effect(Effect::none, nominal, {data}, nullptr);
    Candidate c;
    c.effect = Effect::internal_momentum;
    c.fit = fit_effect(Effect::internal_momentum, nominal, {data}, &none);
    own[static_cast<std::size_t>(f)].candidates.push_back(c);
    own[static_cast<std::size_t>(f)].where.noise_correlation = noise.correlation;
    out.correlation += noise.correlation / kFlights;
    out.true_correlation += g.gyro_noise_correlation / kFlights;
  }
  std::vector<const Analysis*> pointers;
  for (const Analysis& a : own) pointers.push_back(&a);
  const auto scatter = between_flight_scatter(Effect::internal_momentum, pointers);
  REQUIRE(scatter);
  out.scatter = scatter->chi_square_per_dof;
  return out;
}

std::string grid_line(const GridPoint& p, const SessionScatter& s) {
  char line[160];
  std::snprintf(line, sizeof line,
                "%6.0f Hz, %s %4.0f Hz: scatter %6.2f  correlation %6.1f (filter's %6.1f)%s", p.rate_hz,
                p.order == 0   ? "none"
                : p.order == 1 ? "PT1 "
                               : "BW2 ",
                p.cutoff_hz, s.scatter, s.correlation, s.true_correlation,
                s.scatter > kFlightsDisagree ? "  DISAGREE" : "");
  return line;
}

void check_grid(bool small) {
  std::vector<double> all;
  int index = 0, beyond = 0;
  for (const GridPoint& p : grid(small, false)) {
    const SessionScatter s = session_scatter(p, index++);
    all.push_back(s.scatter);
    beyond += s.scatter > kFlightsDisagree;
    std::printf("%s\n", grid_line(p, s).c_str());
  }
  double mean = 0.0, squares = 0.0;
  for (double s : all) mean += s / static_cast<double>(all.size());
  for (double s : all) squares += (s - mean) * (s - mean);
  const double spread = std::sqrt(squares / std::max<double>(1.0, static_cast<double>(all.size()) - 1.0));
  const double expected_spread = std::sqrt(2.0 / ((kFlights - 1) * 3.0));
  std::printf(
      "scatter over %zu sessions: mean %.2f, spread %.2f (for one shared value: 1 +- %.2f); %d beyond %.0f\n",
      all.size(), mean, spread, expected_spread, beyond, kFlightsDisagree);
  CHECK(beyond == 0);
  for (const GridPoint& p : grid(small, true))
    std::printf("not held to the bar: %s\n", grid_line(p, session_scatter(p, index++)).c_str());
  if (small) return;
  // The mean of N sessions lies within 3 standard errors of 1, and their spread within
  // a factor 1.5 of sqrt(2 / dof).
  CHECK(std::abs(mean - 1.0) < 3.0 * expected_spread / std::sqrt(static_cast<double>(all.size())));
  CHECK(spread < 1.5 * expected_spread);
}

}  // namespace

TEST_CASE("flights sharing one rotor agree behind any common gyro filter", "[scatter][filtered]") {
  check_grid(false);
}

TEST_CASE("flights sharing one rotor agree behind a flight controller's PT1", "[scatter][small]") {
  check_grid(true);
}
