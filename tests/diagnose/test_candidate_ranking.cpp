// diagnose/candidate_ranking: held-out gap sums, and how scores become a ranking and a
// verdict (rules in diagnosis.hpp: chi-square plus a penalty per parameter, and a margin
// to beat `none`).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "diagnose/4_judge/candidate_ranking.hpp"
#include "diagnose/4_judge/confidence.hpp"

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
