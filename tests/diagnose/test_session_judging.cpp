// diagnose/4_judge: what a session's verdict says of its flights, moved out of the flow
// (issue 30): the mean flip-period errors (flip_period_summary), the note on flights that
// disagree with the pool (flight_agreement), and the onsets (onset); and when a rotor is
// told apart from its look-alikes (told_apart).
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "diagnose/4_judge/between_flight_scatter.hpp"
#include "diagnose/4_judge/flight_agreement.hpp"
#include "diagnose/4_judge/flip_period_summary.hpp"
#include "diagnose/4_judge/onset.hpp"
#include "diagnose/4_judge/told_apart.hpp"

using namespace aloft::host::diagnose;

namespace {

FlipPeriod period(double measured, double nominal, std::optional<double> diagnosed = std::nullopt) {
  FlipPeriod p;
  p.measured_s = measured;
  p.nominal_s = nominal;
  p.diagnosed_s = diagnosed;
  return p;
}

Flight named(const std::string& name) {
  Flight f;
  f.name = name;
  return f;
}

Analysis saying(Effect effect) {
  Analysis a;
  a.verdict.effect = effect;
  a.verdict.equivalent = {effect};
  return a;
}

// A flight of `n` samples at 100 Hz whose readings sit at sigma = 1 from the model's
// until `jump`, and `step` sigma away after it.
Flight stepping_flight(std::size_t n, std::size_t jump, double step, std::vector<Eigen::Vector3d>& model) {
  Flight f;
  model.clear();
  for (std::size_t k = 0; k < n; ++k) {
    f.time_s.push_back(0.01 * static_cast<double>(k));
    model.push_back(Eigen::Vector3d(1.0, 2.0, 3.0));
    // |residual|^2 / 3 = 1 exactly before the jump: the chi-square excess is 0.
    const double off = k < jump ? 1.0 : step;
    f.omega.push_back(model.back() + Eigen::Vector3d(off, -off, off));
    f.usable.push_back(1);
  }
  return f;
}

}  // namespace

TEST_CASE("flip-period summary: the means over the flights that flip about the intermediate axis",
          "[session_judging]") {
  const std::vector<std::string> comments = {"intermediate, fast", "major axis", "Intermediate",
                                             "intermediate"};
  const std::vector<std::optional<FlipPeriod>> periods = {period(1.0, 1.2, 1.05), period(1.0, 3.0, 1.0),
                                                          period(2.0, 2.2), std::nullopt};
  const std::optional<FlipPeriodSummary> s = summarize_flip_periods(comments, periods);
  REQUIRE(s);
  CHECK(s->flights == 2);  // the major-axis flight and the one without a period left out
  CHECK(s->mean_error_nominal == Approx((0.2 + 0.1) / 2));
  CHECK(s->diagnosed_flights == 1);
  CHECK(s->mean_error_diagnosed == Approx(0.05));
  CHECK(s->fitted_flights == 0);

  // No comment names the axis: every flight with a period counts.
  const std::optional<FlipPeriodSummary> all = summarize_flip_periods({"", "", "", ""}, periods);
  REQUIRE(all);
  CHECK(all->flights == 3);
  CHECK(all->mean_error_nominal == Approx((0.2 + 2.0 + 0.1) / 3));
  CHECK_FALSE(summarize_flip_periods({"a"}, {std::nullopt}));
}

TEST_CASE("flights that disagree with the pool are named; a majority the pool overrules is said so",
          "[session_judging]") {
  const Flight a = named("a"), b = named("b"), c = named("c");
  const std::vector<const Flight*> flights = {&a, &b, &c};
  const Analysis bias = saying(Effect::gyro_bias), drag = saying(Effect::aero_torque);

  Analysis pool = saying(Effect::gyro_bias);
  note_disagreeing_flights(pool, flights, {&bias, &bias, &bias});
  CHECK(pool.notes.empty());  // all agree

  pool = saying(Effect::gyro_bias);
  note_disagreeing_flights(pool, flights, {&bias, &drag, &bias});
  REQUIRE(pool.notes.size() == 1);
  CHECK(pool.notes[0].text == "flights whose own verdict differs from the pool's: b (aero_torque)");

  pool = saying(Effect::gyro_bias);
  note_disagreeing_flights(pool, flights, {&drag, &drag, &bias});
  REQUIRE(pool.notes.size() == 1);
  CHECK(pool.notes[0].text ==
        "2 of 3 flights name aero_torque but the pool does not; flights that disagree with the pool: a "
        "(aero_torque), b (aero_torque)");
}

TEST_CASE("onsets: the CUSUM alarms at a step and never on noise; a session takes the median",
          "[session_judging]") {
  std::vector<Eigen::Vector3d> model;
  const Eigen::Vector3d unit_sigma(1.0, 1.0, 1.0);
  const Flight quiet = stepping_flight(500, 500, 1.0, model);
  CHECK_FALSE(cusum_onset(quiet, model, unit_sigma));
  // After sample 200 the excess is 3^2 - 1 = 8 per sample: the sum passes 15 at the third
  // sample, and the onset is where it last stood at zero, the jump itself.
  const Flight stepping = stepping_flight(500, 200, 3.0, model);
  const std::optional<double> onset = cusum_onset(stepping, model, unit_sigma);
  REQUIRE(onset);
  CHECK(*onset == Approx(2.0));

  Analysis pool = saying(Effect::gyro_bias);
  set_median_onset(pool, {0.4, 0.1, 0.3});
  REQUIRE(pool.where.onset_s);
  CHECK(*pool.where.onset_s == Approx(0.3));
  CHECK(pool.notes.size() == 1);
  pool = saying(Effect::none);  // no effect: no onset to give
  set_median_onset(pool, {0.4, 0.1, 0.3});
  CHECK_FALSE(pool.where.onset_s);
  CHECK(pool.notes.empty());
}

namespace {

// A flight's own analysis with a candidate for `effect`: theta, covariance s^2 I, shrink.
Analysis own_fit(Effect effect, const Eigen::Vector2d& theta, double s, double shrink) {
  Analysis a;
  Candidate c;
  c.effect = effect;
  c.fit.theta = theta;
  c.fit.theta_covariance = Eigen::Matrix2d::Identity() * s * s;
  c.shrink = shrink;
  a.candidates.push_back(c);
  return a;
}

Analysis pooled_verdict(Effect effect, double shrink) {
  Analysis a = saying(effect);
  a.verdict.heldout_rms_rel_err_before = 1.0;
  a.verdict.heldout_rms_rel_err_after = 1.0 - shrink;
  return a;
}

// Five flights' own fits of `effect` with shrink 0.44, each theta known to 0.01 and offset
// from one value by about `scale` standard errors: the offsets have mean 0 and squares
// summing to 5.88 over (5 - 1) x 2 degrees of freedom, a chi-square per dof of 0.735 times
// scale squared.
std::vector<Analysis> five_flights(Effect effect, double scale) {
  const double offsets[5][2] = {{0.8, -1.1}, {-0.6, 0.4}, {1.2, 0.9}, {-1.0, -0.3}, {-0.4, 0.1}};
  std::vector<Analysis> own;
  for (const auto& o : offsets) {
    own.push_back(
        own_fit(effect, Eigen::Vector2d(0.1 + 0.01 * scale * o[0], 0.2 + 0.01 * scale * o[1]), 0.01, 0.44));
  }
  return own;
}

}  // namespace

TEST_CASE("between-flight scatter: flights that share one value read about 1, flights that differ far more",
          "[session]") {
  // Offsets of about one standard error (a shared value), then of ten.
  for (double scale : {1.0, 10.0}) {
    const std::vector<Analysis> own = five_flights(Effect::gyro_scale, scale);
    std::vector<const Analysis*> pointers;
    for (const Analysis& a : own) pointers.push_back(&a);
    const auto scatter = between_flight_scatter(Effect::gyro_scale, pointers);
    REQUIRE(scatter);
    CHECK(scatter->flights == 5);
    CHECK(scatter->median_own_shrink == Approx(0.44));
    CHECK(scatter->chi_square_per_dof == Approx(0.735 * scale * scale));
    Analysis pooled = pooled_verdict(Effect::gyro_scale, 0.35);
    note_between_flight_scatter(pooled, pointers, {});
    CHECK(pooled.notes.size() == (scale > 1.0 ? 1u : 0u));
  }
}

TEST_CASE("between-flight scatter: a noise correlated over neighbouring readings widens each flight's error",
          "[session]") {
  // Flights ten standard errors apart, as the fits count them, but behind a low-pass that
  // makes 20 readings one independent sample: 20 times the variance, 1/20 the chi-square.
  std::vector<Analysis> own = five_flights(Effect::gyro_scale, 10.0);
  for (Analysis& a : own) a.where.noise_correlation = 20.0;
  std::vector<const Analysis*> pointers;
  for (const Analysis& a : own) pointers.push_back(&a);
  const auto scatter = between_flight_scatter(Effect::gyro_scale, pointers);
  REQUIRE(scatter);
  CHECK(scatter->chi_square_per_dof == Approx(0.735 * 100.0 / 20.0));
}

TEST_CASE("a rotor is told apart only in a session whose flights agree on it and where it wins clearly",
          "[session][rotor]") {
  Candidate rotor, rival;
  rotor.effect = Effect::internal_momentum;
  rival.effect = Effect::gyro_bias;
  SECTION("one flight: never, listed beside the other effect") {
    rival.score_behind = 500.0;  // far behind
    rival.score_behind_spread = 10.0;
    const NotToldApart one = told_apart(rotor, &rival, true);
    CHECK_FALSE(one.why.empty());
    CHECK(one.indistinguishable);
  }
  SECTION("a session: a tie is not told apart, a clear win is") {
    rival.score_behind = 30.0;
    rival.score_behind_spread = 20.0;  // within 2 spreads
    CHECK(told_apart(rotor, &rival, false).indistinguishable);
    rival.score_behind = 50.0;  // beyond 2 spreads
    CHECK(told_apart(rotor, &rival, false).why.empty());
    CHECK(told_apart(rotor, nullptr, false).why.empty());
  }
  SECTION("a session whose flights scatter beyond their errors rules it out") {
    // Two parameters stand for the rotor's three: chi-square per dof 0.735, then 73.5.
    for (double scale : {1.0, 10.0}) {
      const std::vector<Analysis> own = five_flights(Effect::internal_momentum, scale);
      std::vector<const Analysis*> pointers;
      for (const Analysis& a : own) pointers.push_back(&a);
      CHECK(flights_disagree_on(rotor, pointers).empty() == (scale == 1.0));
      // Fewer than three flights: no scatter, nothing ruled out.
      pointers.resize(2);
      CHECK(flights_disagree_on(rotor, pointers).empty());
    }
  }
  SECTION("on a base, the flights' own fits of the base and the rotor together are judged") {
    // The flights' rotors fitted alone scatter 73.5 (they took up what the base explains);
    // fitted on the base, 0.735 (they share one h), or 73.5 (they do not).
    const std::vector<Analysis> own = five_flights(Effect::internal_momentum, 10.0);
    std::vector<const Analysis*> pointers;
    for (const Analysis& a : own) pointers.push_back(&a);
    REQUIRE_FALSE(flights_disagree_on(rotor, pointers).empty());
    rotor.base = {Effect::inertia_moments};
    for (double scale : {1.0, 10.0}) {
      rotor.flights_own_fits.clear();
      for (const Analysis& a : five_flights(Effect::internal_momentum, scale)) {
        const EffectFit& fit = a.candidates.front().fit;
        rotor.flights_own_fits.push_back({fit.theta, fit.theta_covariance});
      }
      const std::string why = flights_disagree_on(rotor, pointers);
      CHECK(why.empty() == (scale == 1.0));
      if (!why.empty()) CHECK(why.find("internal_momentum on inertia_moments") == 0);
      // A flight whose fit on the base gave none is left out; fewer than three: nothing ruled out.
      rotor.flights_own_fits.resize(2);
      CHECK(flights_disagree_on(rotor, pointers).empty());
    }
  }
}
