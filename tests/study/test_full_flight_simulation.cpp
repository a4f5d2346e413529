#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "aloft/dynamics/angular_velocity.hpp"
#include "aloft/dynamics/deviation.hpp"
#include "aloft/dynamics/euler_equations.hpp"
#include "aloft/dynamics/rk4_integrator.hpp"
#include "common/commands.hpp"
#include "study/built_in_study.hpp"
#include "study/full_flight_simulation.hpp"
#include "study/study_analyses.hpp"

using namespace aloft::host;

namespace {

aloft::InertiaTensor<double> compound_pendulum() {
  aloft::InertiaTensor<double> cp;
  REQUIRE(aloft::InertiaTensor<double>::make_from_principal(Eigen::Vector3d(203.3e-4, 155.0e-4, 192.5e-4),
                                                            Eigen::Quaterniond::Identity(),
                                                            cp) == aloft::Status::ok);
  return cp;
}

BuiltInTrial noise_free_trial() {
  SyntheticThrowSettings settings;
  settings.marker_noise_m = 0.0;
  return make_built_in_trial(settings);
}

}  // namespace

TEST_CASE("without marker noise the GF model matches the throw from every part of the flight") {
  const BuiltInTrial trial = noise_free_trial();
  REQUIRE(trial.flight.samples() == 873);
  REQUIRE(trial.flight.measured_omega_body.size() == 872);
  const aloft::InertiaTensor<double> cp = compound_pendulum();
  for (std::size_t k :
       {std::size_t(0), std::size_t(1), std::size_t(436), std::size_t(871), std::size_t(872)}) {
    INFO("seeded at sample " << k);
    // Only resampling error remains: a few thousandths of a degree, in either frame.
    const RmsDaByFrame gf = full_flight_rms_da_deg(trial.flight, trial.body.inertia, k);
    CHECK(gf[frame_index(DaFrame::body)] < 0.02);
    CHECK(gf[frame_index(DaFrame::world)] < 0.02);
    // The CP tensor predicts a different motion, seen in either frame.
    const RmsDaByFrame cpv = full_flight_rms_da_deg(trial.flight, cp, k);
    CHECK(cpv[frame_index(DaFrame::body)] > 5.0);
    CHECK(cpv[frame_index(DaFrame::world)] > 1.0);
  }
}

// The seed study's procedure written out plainly, as the reference for the fast loop:
// checked RK4 steps forward and backward (TimeDirection), omega of every interval from
// consecutive orientations (aloft::omega_body_from_orientations), rotated into world axes
// by the interval's first orientation for the world frame, DA, RMS.
RmsDaByFrame reference_rms_da_deg(const StudyFlight& f, const aloft::InertiaTensor<double>& inertia,
                                  std::size_t k) {
  const aloft::Rk4Integrator<double> integrator(inertia);
  const std::size_t n = f.samples();
  std::vector<Eigen::Quaterniond> q(n);
  aloft::RigidBodyState<double> s{f.orientation[k], f.state_omega_body[k]};
  q[k] = s.orientation;
  for (std::size_t j = k; j + 1 < n; ++j) {
    REQUIRE(integrator.step(s, f.time_s[j + 1] - f.time_s[j], aloft::TimeDirection::forward) ==
            aloft::Status::ok);
    q[j + 1] = s.orientation;
  }
  s = {f.orientation[k], f.state_omega_body[k]};
  for (std::size_t j = k; j-- > 0;) {
    REQUIRE(integrator.step(s, f.time_s[j + 1] - f.time_s[j], aloft::TimeDirection::backward) ==
            aloft::Status::ok);
    q[j] = s.orientation;
  }
  double body_sq = 0.0, world_sq = 0.0;
  for (std::size_t j = 0; j + 1 < n; ++j) {
    Eigen::Vector3d w = Eigen::Vector3d::Zero();  // set by the call; zeroed for -Wmaybe-uninitialized
    REQUIRE(aloft::omega_body_from_orientations(q[j], q[j + 1], f.time_s[j + 1] - f.time_s[j], w) ==
            aloft::Status::ok);
    const double body = aloft::deviation_angle(w, f.measured_omega_body[j]);
    const double world = aloft::deviation_angle(Eigen::Vector3d(q[j] * w),
                                                Eigen::Vector3d(f.orientation[j] * f.measured_omega_body[j]));
    body_sq += body * body;
    world_sq += world * world;
  }
  const double to_deg = 180.0 / M_PI, intervals = static_cast<double>(n - 1);
  return {std::sqrt(body_sq / intervals) * to_deg, std::sqrt(world_sq / intervals) * to_deg};
}

TEST_CASE("the fast simulation loop gives the plain procedure's RMS DA") {
  const BuiltInTrial trial = make_built_in_trial();
  const aloft::InertiaTensor<double> cp = compound_pendulum();
  for (std::size_t k : {std::size_t(0), std::size_t(300), std::size_t(872)}) {
    INFO("seeded at sample " << k);
    for (const aloft::InertiaTensor<double>& inertia : {trial.body.inertia, cp}) {
      const RmsDaByFrame fast = full_flight_rms_da_deg(trial.flight, inertia, k);
      const RmsDaByFrame plain = reference_rms_da_deg(trial.flight, inertia, k);
      for (DaFrame frame : kAllDaFrames) {
        INFO(frame_name(frame) << " axes");
        CHECK(fast[frame_index(frame)] == Approx(plain[frame_index(frame)]).epsilon(1e-9));
      }
    }
  }
}

TEST_CASE("a rate flight (gyro) is simulated from body rates and compared at every sample") {
  const aloft::InertiaTensor<double> gf = noise_free_trial().body.inertia;
  std::vector<double> t;
  std::vector<Eigen::Vector3d> w;
  Eigen::Vector3d rate(2.0, -6.0, 5.0);
  for (int i = 0; i <= 500; ++i) {
    t.push_back(0.002 * i);
    w.push_back(rate);
    for (int s = 0; s < 20; ++s) rate = aloft::body_rate_rk4_step(gf, rate, 0.0001);
  }
  const StudyFlight f = make_rate_flight("gyro", t, w);
  validate_study_flight(f);
  const auto body = [&](const aloft::InertiaTensor<double>& inertia, std::size_t k) {
    return full_flight_rms_da_deg(f, inertia, k)[frame_index(DaFrame::body)];
  };
  CHECK(body(gf, 0) < 1e-6);
  CHECK(body(gf, 250) < 1e-6);
  CHECK(body(gf, 500) < 1e-6);
  CHECK(body(compound_pendulum(), 250) > 1.0);
  // No orientation, no world frame.
  CHECK(std::isnan(full_flight_rms_da_deg(f, gf, 250)[frame_index(DaFrame::world)]));
}

TEST_CASE("results do not depend on the number of threads") {
  const BuiltInTrial trial = make_built_in_trial();
  const auto run = [&](unsigned threads) {
    std::vector<Analysis> analyses = {model_analysis("GF", trial.body.inertia)};
    for (Analysis& a : paper_monte_carlo_analyses(40)) analyses.push_back(a);
    RunSettings settings;
    settings.seed = 99;
    settings.threads = threads;
    run_analyses(trial.flight, trial.body.inertia, analyses, settings);
    return analyses;
  };
  const std::vector<Analysis> one = run(1), three = run(3);
  REQUIRE(one.size() == 13);
  for (std::size_t a = 0; a < one.size(); ++a) {
    for (DaFrame frame : kAllDaFrames) {
      REQUIRE(one[a].values(frame).size() == three[a].values(frame).size());
      CHECK(one[a].values(frame) == three[a].values(frame));
    }
  }
  CHECK(one[0].values(DaFrame::world).size() == 873);
  CHECK(one[1].values(DaFrame::body).size() == 40);
}

TEST_CASE("a flight with a bad sample is refused with its name and sample") {
  std::vector<double> t = {0.0, 0.01, 0.02, 0.03};
  std::vector<Eigen::Vector3d> w(4, Eigen::Vector3d(1.0, 2.0, 3.0));
  w[2].y() = std::numeric_limits<double>::quiet_NaN();
  try {
    validate_study_flight(make_rate_flight("segment 4", t, w));
    FAIL("no error");
  } catch (const Error& e) {
    const std::string message = e.what();
    CHECK(message.find("segment 4") != std::string::npos);
    CHECK(message.find("sample 2") != std::string::npos);
  }
  CHECK_THROWS_AS(validate_study_flight(make_rate_flight("short", {0.0, 0.1}, {w[0], w[1]})), Error);
}
