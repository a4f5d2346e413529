// diagnose/candidate_ranking: held-out gap sums, and how scores become a ranking and a
// verdict (rules in diagnosis.hpp: chi-square plus a penalty per parameter, and a margin
// to beat `none`).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "diagnose/4_judge/candidate_ranking.hpp"
#include "diagnose/4_judge/confidence.hpp"
#include "diagnose/4_judge/score_spread.hpp"
#include "diagnose/2_model/nominal_inertia.hpp"

using namespace aloft::host::diagnose;

TEST_CASE("GapSums: DA, relative error and chi-square of known vectors", "[candidate_ranking]") {
  GapSums sums;
  const Eigen::Vector3d unit_sigma(1.0, 1.0, 1.0);
  sums.add(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), unit_sigma);  // 90 deg, rel sqrt 2
  sums.add(Eigen::Vector3d(0, 2, 0), Eigen::Vector3d(0, 1, 0), unit_sigma);  // 0 deg, rel 1
  CHECK(sums.samples == 2);
  CHECK(sums.residuals == 6);
  CHECK(sums.rms_da_deg() == Approx(std::sqrt(90.0 * 90.0 / 2.0)));
  CHECK(sums.rms_rel_err() == Approx(std::sqrt((2.0 + 1.0) / 2.0)));
  CHECK(sums.chi_square == Approx(2.0 + 1.0));
  GapSums weighted;
  weighted.add(Eigen::Vector3d(0.1, 0, 0), Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(10, 1, 1));
  CHECK(weighted.chi_square == Approx(1.0));  // residual over sigma
  CHECK(weighted.samples == 0);               // no direction to compare with a zero rate
}

namespace {

Candidate candidate(Effect effect, double chi_square, double rel_err) {
  Candidate c;
  c.effect = effect;
  c.heldout_chi_square = chi_square;
  c.heldout_residuals = 3000;
  c.heldout_rms_rel_err = rel_err;
  c.heldout_rms_da_deg = 10.0 * rel_err;
  const int n = effect_penalty_count(effect);
  c.fit.theta = Eigen::VectorXd::Constant(n, 0.1);
  c.fit.theta_standard_error = Eigen::VectorXd::Constant(n, 1e-6);  // well determined
  return c;
}

double penalty(Effect e) { return kPenaltyPerParameter * effect_penalty_count(e); }

Analysis ranked(std::vector<Candidate> candidates, bool gyro_input = true) {
  Analysis a;
  a.candidates = std::move(candidates);
  rank_candidates(a, gyro_input, {}, {}, 10.0, 1.0);
  return a;
}

}  // namespace

TEST_CASE("rank_candidates: a clear gain wins, best first, shrink against none", "[candidate_ranking]") {
  const double gain = kVerdictMargin + penalty(Effect::gyro_bias) + 50.0;
  const Analysis a =
      ranked({candidate(Effect::none, 2900.0, 0.10), candidate(Effect::gyro_scale, 2890.0, 0.098),
              candidate(Effect::gyro_bias, 2900.0 - gain, 0.05)});
  REQUIRE(a.candidates.size() == 3);
  CHECK(a.candidates.front().effect == Effect::gyro_bias);
  for (std::size_t i = 1; i < a.candidates.size(); ++i) {
    CHECK(a.candidates[i - 1].score <= a.candidates[i].score);
  }
  CHECK(a.verdict.effect == Effect::gyro_bias);
  CHECK(a.verdict.heldout_rms_rel_err_before == Approx(0.10));
  CHECK(a.verdict.heldout_rms_rel_err_after == Approx(0.05));
  CHECK(a.candidates.front().shrink == Approx(0.5));
}

TEST_CASE("rank_candidates: a gain within the margin is noise, and the verdict is none",
          "[candidate_ranking]") {
  const double gain = kVerdictMargin + penalty(Effect::gyro_bias) - 5.0;
  const Analysis a =
      ranked({candidate(Effect::none, 2900.0, 0.10), candidate(Effect::gyro_bias, 2900.0 - gain, 0.099)});
  CHECK(a.verdict.effect == Effect::none);
}

TEST_CASE("rank_candidates: an unphysical fit never wins, however well it scores", "[candidate_ranking]") {
  Candidate drag = candidate(Effect::aero_torque, 1000.0, 0.01);
  drag.fit.theta(0) = -5.0;  // negative drag: energy gained
  const double gain = kVerdictMargin + penalty(Effect::gyro_bias) + 100.0;
  const Analysis a = ranked(
      {candidate(Effect::none, 2900.0, 0.10), drag, candidate(Effect::gyro_bias, 2900.0 - gain, 0.05)});
  CHECK(a.verdict.effect == Effect::gyro_bias);
  for (const Candidate& c : a.candidates) {
    if (c.effect == Effect::aero_torque) CHECK_FALSE(c.physical);
  }
}

TEST_CASE("rank_candidates: a verdict names the effects a gyro cannot tell from it", "[candidate_ranking]") {
  const double gain = kVerdictMargin + penalty(Effect::inertia_axes) + 50.0;
  const Analysis a =
      ranked({candidate(Effect::none, 2900.0, 0.10), candidate(Effect::inertia_axes, 2900.0 - gain, 0.05)});
  REQUIRE(a.verdict.effect == Effect::inertia_axes);
  const auto& eq = a.verdict.equivalent;
  CHECK(std::find(eq.begin(), eq.end(), Effect::sensor_misalignment) != eq.end());
}

TEST_CASE("rank_candidates: a winner with poorly determined parameters is not confident",
          "[candidate_ranking]") {
  Candidate bias = candidate(Effect::gyro_bias, 2000.0, 0.05);
  bias.fit.theta_standard_error.setConstant(1.0);  // far beyond the tolerance
  const Analysis a = ranked({candidate(Effect::none, 2900.0, 0.10), bias});
  CHECK(a.verdict.effect == Effect::gyro_bias);
  CHECK_FALSE(a.verdict.confident);
  CHECK_FALSE(a.candidates.front().identifiable);
}

TEST_CASE("rank_step: a class that ties exactly is headed by the registry's first, whichever fit ended lower",
          "[candidate_ranking][ties]") {
  // inertia_axes and sensor_misalignment are one class from a gyro (the same predictions):
  // which scores a bit lower is the last bits of the fits, not the data.
  const double gain = kVerdictMargin + penalty(Effect::inertia_axes) + 50.0;
  for (double last_bits : {-1e-9, 0.0, 1e-9, 0.3}) {
    const Analysis a = ranked({candidate(Effect::none, 2900.0, 0.10),
                               candidate(Effect::sensor_misalignment, 2900.0 - gain - last_bits, 0.05),
                               candidate(Effect::inertia_axes, 2900.0 - gain, 0.05)});
    CHECK(a.verdict.effect == Effect::inertia_axes);
    REQUIRE(a.verdict.equivalent.size() == 2);
    CHECK(a.verdict.equivalent[1] == Effect::sensor_misalignment);
    CHECK(a.verdict.indistinguishable.empty());
  }
}

TEST_CASE("rank_step: a class that ties is listed in the registry's order, whichever fit ended lower",
          "[candidate_ranking][ties]") {
  const double gain = kVerdictMargin + penalty(Effect::inertia_axes) + 50.0;
  for (double last_bits : {-0.3, -1e-9, 0.0, 1e-9, 0.3}) {
    const Analysis a = ranked({candidate(Effect::none, 2900.0, 0.10),
                               candidate(Effect::sensor_misalignment, 2900.0 - gain - last_bits, 0.05),
                               candidate(Effect::inertia_axes, 2900.0 - gain, 0.05)});
    REQUIRE(a.candidates.size() == 3);
    CHECK(a.candidates[0].effect == Effect::inertia_axes);
    CHECK(a.candidates[1].effect == Effect::sensor_misalignment);
    CHECK(a.candidates[2].effect == Effect::none);
    CHECK(a.candidates[static_cast<std::size_t>(a.verdict.chosen)].effect == a.verdict.effect);
  }
  // Beyond the rounding tolerance the scores order them.
  const Analysis apart = ranked({candidate(Effect::none, 2900.0, 0.10),
                                 candidate(Effect::sensor_misalignment, 2900.0 - gain - 2.0, 0.05),
                                 candidate(Effect::inertia_axes, 2900.0 - gain, 0.05)});
  CHECK(apart.candidates[0].effect == Effect::sensor_misalignment);
}

TEST_CASE("rank_step: a class member clearly ahead keeps the headline", "[candidate_ranking][ties]") {
  const double gain = kVerdictMargin + penalty(Effect::inertia_axes) + 50.0;
  const Analysis a = ranked({candidate(Effect::none, 2900.0, 0.10),
                             candidate(Effect::sensor_misalignment, 2900.0 - gain - 10.0, 0.05),
                             candidate(Effect::inertia_axes, 2900.0 - gain, 0.05)});
  CHECK(a.verdict.effect == Effect::sensor_misalignment);
}

TEST_CASE(
    "rank_step: candidates of different classes within rounding are named in registry order, "
    "indistinguishable and not confident",
    "[candidate_ranking][ties]") {
  const double gain = kVerdictMargin + penalty(Effect::gyro_bias) + 50.0;
  // gyro_scale ends a hair lower than gyro_bias once the penalties are counted.
  const double scale_score = 2900.0 - gain - penalty(Effect::gyro_scale) + penalty(Effect::gyro_bias) -
                             0.5 * kScoreRoundingTolerance;
  const Analysis a =
      ranked({candidate(Effect::none, 2900.0, 0.10), candidate(Effect::gyro_bias, 2900.0 - gain, 0.05),
              candidate(Effect::gyro_scale, scale_score, 0.05)});
  CHECK(a.verdict.effect == Effect::gyro_bias);  // before gyro_scale in the registry
  REQUIRE(a.verdict.indistinguishable.size() == 1);
  CHECK(a.verdict.indistinguishable[0] == Effect::gyro_scale);
  CHECK_FALSE(a.verdict.confident);
  REQUIRE_FALSE(a.verdict.could_not_judge.empty());
  CHECK(a.verdict.could_not_judge.front().find("indistinguishable") != std::string::npos);
}

namespace {

// A flight of n samples at rest, sigma 1, and a candidate whose held-out predictions miss
// each sample by `miss(k)` along x.
Flight still_flight(std::size_t n) {
  Flight f;
  for (std::size_t k = 0; k < n; ++k) {
    f.time_s.push_back(0.001 * static_cast<double>(k));
    f.omega.push_back(Eigen::Vector3d::Zero());
    f.usable.push_back(1);
  }
  return f;
}

template <class Miss>
Candidate missing_by(Effect effect, const Flight& flight, Miss miss) {
  Candidate c = candidate(effect, 0.0, 0.05);
  std::vector<Eigen::Vector3d> predicted(flight.size(), Eigen::Vector3d::Zero());
  for (std::size_t k = 0; k < flight.size(); ++k) {
    predicted[k].x() = miss(k);
    c.heldout_chi_square += miss(k) * miss(k);
  }
  c.heldout_residuals = 3 * static_cast<int>(flight.size());
  c.heldout_readings.push_back(predicted);
  return c;
}

}  // namespace

TEST_CASE("score_spread: a sum's spread over chunks, and a paired difference's", "[score_spread][ties]") {
  CHECK(spread_of_sum({}) == 0.0);
  CHECK(spread_of_sum({3.0}) == 0.0);
  CHECK(spread_of_sum({1.0, 1.0, 1.0, 1.0}) == 0.0);
  // Values 0 and 2 alternating: standard deviation sqrt(4/3) over four, sum's spread 2 sqrt(4/3).
  CHECK(spread_of_sum({0.0, 2.0, 0.0, 2.0}) == Approx(2.0 * std::sqrt(4.0 / 3.0)));
  // What two candidates share cancels in their difference.
  CHECK(spread_of_difference({5.0, 9.0, 1.0}, {4.0, 8.0, 0.0}) == Approx(0.0).margin(1e-12));
  const Flight flight = still_flight(400);  // chunks of 20 samples
  const Candidate c = missing_by(Effect::gyro_bias, flight, [](std::size_t k) { return k < 20 ? 1.0 : 0.0; });
  const std::vector<double> chunks = chunk_chi_squares(c, {&flight}, {Eigen::Vector3d::Ones()});
  REQUIRE(chunks.size() == 20);
  CHECK(chunks[0] == Approx(20.0));
  CHECK(chunks[1] == 0.0);
}

TEST_CASE("rank_step: a margin within twice the spread of the difference is a tie",
          "[candidate_ranking][ties]") {
  const Flight flight = still_flight(2000);  // 20 chunks of 100 samples
  RankingContext context;
  context.flights = {&flight};
  context.inverse_sigma = {Eigen::Vector3d::Ones()};
  context.mean_speed = 10.0;
  context.duration_s = 1.0;
  // none misses everywhere by 1, bias by 0.5 (chi-square 500); scale by -0.4 and 0.6 in
  // alternate chunks (520): 20 behind, but its chunks differ from bias's by -9 and +11,
  // a spread of the difference of about 46. The predictions differ by 0.9 and 0.1
  // (0.37 sigma RMS), so the data does not make them one class either.
  const auto bias_miss = [](std::size_t) { return 0.5; };
  const auto scale_miss = [](std::size_t k) { return (k / 100) % 2 == 0 ? -0.4 : 0.6; };
  Analysis a;
  a.candidates = {missing_by(Effect::none, flight, [](std::size_t) { return 1.0; }),
                  missing_by(Effect::gyro_bias, flight, bias_miss),
                  missing_by(Effect::gyro_scale, flight, scale_miss)};
  rank_candidates(a, context);
  REQUIRE(a.verdict.effect != Effect::none);
  CHECK(a.verdict.effect == Effect::gyro_bias);
  const std::vector<Effect>& tied = a.verdict.indistinguishable;
  REQUIRE(tied.size() == 1);
  CHECK(tied[0] == Effect::gyro_scale);
  CHECK_FALSE(a.verdict.confident);
  for (const Candidate& c : a.candidates) {
    if (c.effect == Effect::gyro_scale) {
      CHECK(c.score_behind == Approx(20.0));
      CHECK(c.score_behind_spread == Approx(std::sqrt(20.0 * 20.0 * 100.0 / 19.0)));
      CHECK(c.score_spread == Approx(c.score_behind_spread));  // bias's chunks are all alike
    }
    if (c.effect == Effect::gyro_bias) CHECK(c.score_behind == 0.0);
  }
  // The same two with the scale's misses even: no tie, the better one alone.
  Analysis b;
  b.candidates = {missing_by(Effect::none, flight, [](std::size_t) { return 1.0; }),
                  missing_by(Effect::gyro_bias, flight, bias_miss),
                  missing_by(Effect::gyro_scale, flight, [](std::size_t) { return 0.45; })};
  rank_candidates(b, context);
  CHECK(b.verdict.effect == Effect::gyro_scale);
  CHECK(b.verdict.indistinguishable.empty());
}

TEST_CASE("rank_step: another minimum of a search is reported when it fits about as well",
          "[candidate_ranking][ties]") {
  const double gain = kVerdictMargin + penalty(Effect::impulse) + 50.0;
  Candidate none = candidate(Effect::none, 2900.0, 0.10);
  none.fit.cost = 3000.0;
  Candidate knock = candidate(Effect::impulse, 2900.0 - gain, 0.05);
  knock.fit.cost = 2900.0;
  knock.fit.residual_count = 3000;
  const auto other_at = [](double cost, double time_s) {
    OtherMinimum m;
    m.theta = Eigen::VectorXd::Constant(3, 0.01);
    m.impulse_time_s = time_s;
    m.cost = cost;
    return m;
  };
  knock.fit.other_minima = {other_at(2900.0 + 0.5 * kCloseMinimum, 0.4),  // close: reported
                            other_at(2900.0 + 2.0 * kCloseMinimum, 0.6),  // farther: not
                            other_at(2900.0 + 0.1 * kSameMinimum, 0.8)};  // the same minimum
  const Analysis a = ranked({none, knock});
  REQUIRE(a.verdict.effect == Effect::impulse);
  const Candidate& chosen = a.candidates[static_cast<std::size_t>(a.verdict.chosen)];
  REQUIRE(chosen.alternatives.size() == 1);
  CHECK(chosen.alternatives[0].cost_behind == Approx(0.5 * kCloseMinimum));
  REQUIRE(a.notes.size() == 1);
  CHECK(a.notes[0].text.find("another minimum") != std::string::npos);
  // The note carries the other minimum's parameters; the report words them (effect_words).
  REQUIRE(a.notes[0].params_of.has_value());
  CHECK(*a.notes[0].params_of == Effect::impulse);
  CHECK(a.notes[0].params.time_s == chosen.alternatives[0].params.time_s);
}

namespace {

// A moments verdict and a gyro scale that fits as well with the same predictions, ranked
// on a flight read by a gyro turned by `sensor_to_body`.
Analysis moments_with_scale(const Eigen::Quaterniond& sensor_to_body, Effect head) {
  static const NominalInertia nominal =
      NominalInertia::of_tensor(Eigen::Vector3d(0.002, 0.004, 0.005).asDiagonal());
  Flight flight;
  flight.sensor_to_body = sensor_to_body;
  for (int k = 0; k < 10; ++k) {
    flight.time_s.push_back(0.01 * k);
    flight.omega.emplace_back(1.0, 8.0, 0.5);
    flight.usable.push_back(1);
  }
  // Scores (chi-square plus the penalties) 2000 for the head, 2003 for the other: beyond
  // the rounding tolerance that names a tie by registry order, within the class margin.
  const auto score = [&](Effect e) { return (e == head ? 2000.0 : 2003.0) - penalty(e); };
  Candidate moments = candidate(Effect::inertia_moments, score(Effect::inertia_moments), 0.05);
  moments.params.principal_kg_m2 = Eigen::Vector3d(0.0021, 0.004, 0.0049);  // the nominal order kept
  Candidate scale = candidate(Effect::gyro_scale, score(Effect::gyro_scale), 0.05);
  for (Candidate* c : {&moments, &scale}) c->heldout_readings = {flight.omega};  // the same predictions
  Analysis a;
  a.candidates = {candidate(Effect::none, 2900.0, 0.10), moments, scale};
  RankingContext context;
  context.flights = {&flight};
  context.inverse_sigma = {Eigen::Vector3d::Constant(50.0)};
  context.mean_speed = 10.0;
  context.duration_s = 1.0;
  context.nominal = &nominal;
  rank_candidates(a, context);
  return a;
}

bool lists(const std::vector<Effect>& list, Effect e) {
  return std::find(list.begin(), list.end(), e) != list.end();
}

}  // namespace

TEST_CASE("one-way equivalence: a scale is listed with moments only where it mimics them, never the reverse",
          "[candidate_ranking]") {
  const Eigen::Quaterniond along_axes = Eigen::Quaterniond::Identity();
  const Eigen::Quaterniond turned(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()));
  const Analysis mimicked = moments_with_scale(along_axes, Effect::inertia_moments);
  REQUIRE(mimicked.verdict.effect == Effect::inertia_moments);
  CHECK(lists(mimicked.verdict.equivalent, Effect::gyro_scale));
  // A gyro turned from the principal axes mixes the rates: no scale mimics the moments.
  const Analysis mixed = moments_with_scale(turned, Effect::inertia_moments);
  REQUIRE(mixed.verdict.effect == Effect::inertia_moments);
  CHECK_FALSE(lists(mixed.verdict.equivalent, Effect::gyro_scale));
  // Moments never stand in for a scale.
  const Analysis scale_first = moments_with_scale(along_axes, Effect::gyro_scale);
  REQUIRE(scale_first.verdict.effect == Effect::gyro_scale);
  CHECK_FALSE(lists(scale_first.verdict.equivalent, Effect::inertia_moments));
}
