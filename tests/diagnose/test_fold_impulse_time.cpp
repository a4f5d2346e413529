// diagnose/fold_impulse_time: where a fold cannot see an impulse's jump, every time in the
// gap between its training samples fits them alike, and the fold's jump goes to the
// gap's middle, whatever time its search stopped at.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

#include "diagnose/2_model/flight_model.hpp"
#include "diagnose/3_fit/fold_impulse_time.hpp"
#include "diagnose/3_fit/held_out.hpp"

using namespace aloft::host::diagnose;

namespace {

// A noise-free 0.3 s flight at 1 kHz of the nominal body with a jump of the rate just
// before sample 151 (0.1505 s).
constexpr std::size_t kSamples = 300;
constexpr double kJumpS = 0.1505;

Flight impulse_flight(const NominalInertia& nominal) {
  Flight flight;
  for (std::size_t k = 0; k < kSamples; ++k) flight.time_s.push_back(0.001 * static_cast<double>(k));
  flight.usable.assign(kSamples, 1);
  flight.omega.assign(kSamples, Eigen::Vector3d::Zero());
  Eigen::VectorXd jump(3);
  jump << 0.004, -0.002, 0.003;  // angular impulse, N m s
  predict_readings(EffectModel(Effect::impulse, nominal, kJumpS), flight, 0, Eigen::Vector3d(3.0, 5.0, -2.0),
                   jump, flight.omega);
  return flight;
}

}  // namespace

TEST_CASE("fold_impulse_fit: a jump the fold cannot see goes to the middle of its gap",
          "[fold_impulse_time]") {
  const NominalInertia nominal = NominalInertia::of_tensor(Eigen::Vector3d(0.01, 0.02, 0.03).asDiagonal());
  const Flight flight = impulse_flight(nominal);
  const Folds folds = interleaved_folds(kSamples);
  // The fold that judges the samples either side of the jump.
  const std::size_t f = folds.train[0][150] ? 1 : 0;
  REQUIRE(!folds.train[f][150]);
  REQUIRE(!folds.train[f][151]);
  const FlightData train{&flight, folds.train[f], Eigen::Vector3d::Constant(50.0)};
  const EffectFit none = fit_effect(Effect::none, nominal, {train}, nullptr);
  const EffectFit searched = fit_effect(Effect::impulse, nominal, {train}, &none);

  // The gap: the judged chunk that holds the jump, between two training samples.
  const SampleRange gap = unseen_jump_gap(searched, train);
  REQUIRE(gap.first < 151);
  REQUIRE(gap.end > 151);
  CHECK(folds.train[f][gap.first - 1]);
  CHECK(folds.train[f][gap.end]);
  for (std::size_t k = gap.first; k < gap.end; ++k) CHECK(!folds.train[f][k]);

  // The tie: at every time in the gap the training samples are fitted alike (here
  // exactly, to 1e-12: the data are noise-free), while a time in the next judged chunk
  // misses them (0.86).
  const auto cost_at = [&](double time_s) {
    EffectFit fit = searched;
    for (int step = 0; step < 4; ++step) fit = refit_from_solution(fit, nominal, train, time_s);
    return fit.cost;
  };
  for (std::size_t k = gap.first; k <= gap.end; k += 3) {
    CHECK(cost_at(0.5 * (flight.time_s[k - 1] + flight.time_s[k])) < 1e-9);
  }
  CHECK(cost_at(0.5 * (flight.time_s[gap.end + 19] + flight.time_s[gap.end + 20])) > 0.1);

  // The fold's jump in the middle of the gap, whichever time the search had reached.
  const std::size_t middle = (gap.first + gap.end) / 2;
  const double middle_s = 0.5 * (flight.time_s[middle - 1] + flight.time_s[middle]);
  for (std::size_t k : {gap.first, middle + 2, gap.end}) {
    EffectFit stopped = searched;
    stopped.flights[0].impulse_time_s = 0.5 * (flight.time_s[k - 1] + flight.time_s[k]);
    const EffectFit centred = fold_impulse_fit(stopped, stopped, nominal, train);
    CHECK(centred.flights[0].impulse_time_s == middle_s);
    CHECK(centred.cost < 1e-9);
  }
}

TEST_CASE("unseen_jump_gap: none where training samples lie next to the jump", "[fold_impulse_time]") {
  const NominalInertia nominal = NominalInertia::of_tensor(Eigen::Vector3d(0.01, 0.02, 0.03).asDiagonal());
  const Flight flight = impulse_flight(nominal);
  const Folds folds = interleaved_folds(kSamples);
  const std::size_t f = folds.train[0][150] ? 0 : 1;  // the fold that sees the jump
  REQUIRE(folds.train[f][150]);
  REQUIRE(folds.train[f][151]);
  EffectFit fit;
  fit.effect = Effect::impulse;
  fit.flights.resize(1);
  fit.flights[0].impulse_time_s = kJumpS;
  const SampleRange gap = unseen_jump_gap(fit, FlightData{&flight, folds.train[f], Eigen::Vector3d::Ones()});
  CHECK(gap.first == gap.end);
}
