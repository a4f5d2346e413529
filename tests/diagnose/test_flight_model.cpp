// diagnose/flight_model: the forward model's readings against exact answers. At 1 kHz
// the model takes one step every few samples and interpolates the readings between them
// (flight_model.cpp, ReadingWalks); these tests hold it to a body whose motion is known in
// closed form and to the two conserved quantities of any torque-free body.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>

#include "diagnose/2_model/flight_model.hpp"
#include "diagnose/2_model/reading_derivatives.hpp"

using namespace aloft::host::diagnose;

namespace {

// 1.2 s at 1 kHz, gyro along the body axes.
Flight kilohertz_flight() {
  Flight f;
  for (int k = 0; k < 1200; ++k) {
    f.time_s.push_back(0.001 * k);
    f.omega.emplace_back(0.0, 0.0, 0.0);
    f.usable.push_back(1);
  }
  return f;
}

}  // namespace

TEST_CASE("an axisymmetric body's rate turns about its axis at (C - A) / A w3, every sample to 2e-6 rad/s",
          "[flight_model]") {
  const double a = 0.002, c = 0.0035;
  const NominalInertia body = NominalInertia::of_tensor(Eigen::Vector3d(a, a, c).asDiagonal());
  const Flight flight = kilohertz_flight();
  const std::size_t ref = flight.size() / 2;
  const Eigen::Vector3d w0(4.0, -2.0, 12.0);  // |w| 13.6 rad/s
  std::vector<Eigen::Vector3d> readings;
  predict_readings(EffectModel(Effect::none, body), flight, ref, w0, Eigen::VectorXd(), readings);
  // Euler: A w1' = (A - C) w2 w3, A w2' = (C - A) w3 w1, so w1 + i w2 turns at lambda.
  const double lambda = (c - a) / a * w0(2);
  double largest = 0.0;
  for (std::size_t k = 0; k < flight.size(); ++k) {
    const double t = flight.time_s[k] - flight.time_s[ref];
    const std::complex<double> across = std::complex<double>(w0(0), w0(1)) * std::polar(1.0, lambda * t);
    const Eigen::Vector3d exact(across.real(), across.imag(), w0(2));
    largest = std::max(largest, (readings[k] - exact).norm());
  }
  INFO("largest error " << largest << " rad/s");
  // Measured 8.3e-7 (6e-8 of the rate), from RK4 at 5 ms with cubic Hermite between; a
  // gyro's noise is 0.005-0.02 rad/s.
  CHECK(largest < 2e-6);
}

TEST_CASE("a tumbling asymmetric body keeps its energy and |L| at every 1 kHz sample to 2e-7",
          "[flight_model]") {
  const Eigen::Vector3d moments(0.0017, 0.0042, 0.0054);
  const NominalInertia body = NominalInertia::of_tensor(moments.asDiagonal());
  const Flight flight = kilohertz_flight();
  const std::size_t ref = flight.size() / 2;
  const Eigen::Vector3d w0(0.3, 14.0, 0.5);  // about the intermediate axis: flips
  std::vector<Eigen::Vector3d> readings;
  predict_readings(EffectModel(Effect::none, body), flight, ref, w0, Eigen::VectorXd(), readings);
  const auto energy = [&](const Eigen::Vector3d& w) { return w.dot(moments.cwiseProduct(w)); };
  const auto momentum = [&](const Eigen::Vector3d& w) { return moments.cwiseProduct(w).norm(); };
  double energy_drift = 0.0, momentum_drift = 0.0;
  for (const Eigen::Vector3d& w : readings) {
    energy_drift = std::max(energy_drift, std::abs(energy(w) / energy(w0) - 1.0));
    momentum_drift = std::max(momentum_drift, std::abs(momentum(w) / momentum(w0) - 1.0));
  }
  INFO("energy " << energy_drift << ", |L| " << momentum_drift);
  CHECK(energy_drift < 2e-7);    // measured 6.3e-8
  CHECK(momentum_drift < 2e-7);  // measured 3.2e-8
}

TEST_CASE("steps shared by 1 kHz samples read as one step a sample does, to 3e-6 rad/s, impulse included",
          "[flight_model]") {
  const NominalInertia body = NominalInertia::of_tensor(Eigen::Vector3d(0.0017, 0.0042, 0.0054).asDiagonal());
  const Flight flight = kilohertz_flight();
  const Eigen::Vector3d w0(0.3, 14.0, 0.5);
  for (const double impulse_time : {0.25, 0.9005}) {  // before and after the reference, between samples
    EffectModel model(Effect::impulse, body, impulse_time);
    const Eigen::Vector3d jump(0.5, -0.3, 0.8);
    std::vector<Eigen::Vector3d> shared, per_sample;
    const std::size_t ref = flight.size() / 2;
    predict_readings(model, flight, ref, w0, jump, shared, SampleStepping::shared_steps);
    predict_readings(model, flight, ref, w0, jump, per_sample, SampleStepping::step_per_sample);
    double largest = 0.0;
    for (std::size_t k = 0; k < flight.size(); ++k)
      largest = std::max(largest, (shared[k] - per_sample[k]).norm());
    INFO("impulse at " << impulse_time << " s: largest difference " << largest << " rad/s");
    CHECK(largest > 0.0);   // the two really step differently
    CHECK(largest < 3e-6);  // measured 1.6e-6 on this flip at 14 rad/s
  }
}

namespace {

// A flight read through a gyro turned from the body axes, so that every sensor term counts.
Flight turned_gyro_flight() {
  Flight f = kilohertz_flight();
  f.sensor_to_body = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()));
  return f;
}

}  // namespace

TEST_CASE("the sensor's columns of the readings' Jacobian agree with central differences of the prediction",
          "[flight_model]") {
  const NominalInertia body = NominalInertia::of_tensor(Eigen::Vector3d(0.0017, 0.0042, 0.0054).asDiagonal());
  const Flight flight = turned_gyro_flight();
  const std::size_t ref = flight.size() / 2;
  const Eigen::Vector3d w0(0.3, 14.0, 0.5);
  struct Case {
    EffectModel model;
    Eigen::VectorXd theta;
    std::vector<char> sensor;  // which theta entries only the sensor sees
  };
  Eigen::VectorXd bias(3), scale(3), turn(3), axes_then_bias(6);
  bias << 0.05, -0.02, 0.1;
  scale << 0.03, -0.05, 0.02;
  turn << 0.04, -0.06, 0.1;
  axes_then_bias << 0.05, 0.02, -0.03, 0.05, -0.02, 0.1;
  const std::vector<Case> cases = {
      {EffectModel(Effect::gyro_bias, body), bias, {1, 1, 1}},
      {EffectModel(Effect::gyro_scale, body), scale, {1, 1, 1}},
      {EffectModel(Effect::sensor_misalignment, body), turn, {1, 1, 1}},
      {EffectModel(Effect::gyro_bias, body, 0.0, {Effect::inertia_axes}), axes_then_bias, {0, 0, 0, 1, 1, 1}},
  };
  for (const Case& c : cases) {
    CAPTURE(effect_name(c.model.effect), c.model.base.size());
    REQUIRE(sensor_directions(c.model, c.theta) == c.sensor);
    std::vector<Eigen::Vector3d> readings, up, down;
    predict_readings(c.model, flight, ref, w0, c.theta, readings);
    Eigen::MatrixXd columns =
        Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(3 * flight.size()), c.theta.size());
    sensor_reading_derivatives(c.model, flight, c.theta, readings, c.sensor, columns);
    for (Eigen::Index i = 0; i < c.theta.size(); ++i) {
      if (!c.sensor[static_cast<std::size_t>(i)]) {
        CHECK(columns.col(i).isZero(0.0));
        continue;
      }
      const double h = 1e-5;
      Eigen::VectorXd plus = c.theta, minus = c.theta;
      plus(i) += h;
      minus(i) -= h;
      predict_readings(c.model, flight, ref, w0, plus, up);
      predict_readings(c.model, flight, ref, w0, minus, down);
      double largest = 0.0, size = 0.0;
      for (std::size_t k = 0; k < flight.size(); ++k) {
        const Eigen::Vector3d central = (up[k] - down[k]) / (2.0 * h);
        largest =
            std::max(largest, (columns.block<3, 1>(static_cast<Eigen::Index>(3 * k), i) - central).norm());
        size = std::max(size, central.norm());
      }
      INFO("column " << i << ": largest difference " << largest << " of " << size);
      CHECK(size > 0.1);
      CHECK(largest < 1e-7 * size);  // measured <= 2.2e-10 of the column: the central differences' own error
    }
  }
}

TEST_CASE("the impulse's Jacobian columns, carried by the flow map, agree with central differences",
          "[flight_model]") {
  const NominalInertia body = NominalInertia::of_tensor(Eigen::Vector3d(0.0017, 0.0042, 0.0054).asDiagonal());
  const Flight flight = turned_gyro_flight();
  const std::size_t ref = flight.size() / 2;
  const Eigen::Vector3d w0(0.3, 14.0, 0.5);
  Eigen::VectorXd jump(3);
  jump << 0.5, -0.3, 0.8;
  for (const double impulse_time : {0.25, 0.9005}) {  // before and after the reference
    const EffectModel model(Effect::impulse, body, impulse_time);
    REQUIRE(impulse_directions(model, jump) == std::vector<char>{1, 1, 1});
    REQUIRE(sensor_directions(model, jump) == std::vector<char>{0, 0, 0});
    const double h = 1e-5;
    // d readings / d omega_ref and d rate_at_impulse / d omega_ref, by central differences.
    Eigen::MatrixXd rate_columns(3 * flight.size(), 3);
    Eigen::Matrix3d at_impulse_derivative;
    std::vector<Eigen::Vector3d> up, down;
    for (int i = 0; i < 3; ++i) {
      Eigen::Vector3d rate_up, rate_down;
      predict_readings(model, flight, ref, w0 + h * Eigen::Vector3d::Unit(i), jump, up,
                       SampleStepping::shared_steps, &rate_up);
      predict_readings(model, flight, ref, w0 - h * Eigen::Vector3d::Unit(i), jump, down,
                       SampleStepping::shared_steps, &rate_down);
      for (std::size_t k = 0; k < flight.size(); ++k) {
        rate_columns.block<3, 1>(static_cast<Eigen::Index>(3 * k), i) = (up[k] - down[k]) / (2.0 * h);
      }
      at_impulse_derivative.col(i) = (rate_up - rate_down) / (2.0 * h);
    }
    Eigen::MatrixXd jacobian(3 * flight.size(), 6);
    jacobian.rightCols(3) = rate_columns;
    impulse_reading_derivatives(model, flight, ref, jump, at_impulse_derivative, {1, 1, 1}, jacobian);
    const Eigen::MatrixXd columns = jacobian.leftCols(3);
    CHECK(jacobian.rightCols(3) == rate_columns);
    for (Eigen::Index i = 0; i < 3; ++i) {
      Eigen::VectorXd plus = jump, minus = jump;
      plus(i) += h;
      minus(i) -= h;
      predict_readings(model, flight, ref, w0, plus, up);
      predict_readings(model, flight, ref, w0, minus, down);
      double largest = 0.0, size = 0.0;
      for (std::size_t k = 0; k < flight.size(); ++k) {
        const Eigen::Vector3d central = (up[k] - down[k]) / (2.0 * h);
        largest =
            std::max(largest, (columns.block<3, 1>(static_cast<Eigen::Index>(3 * k), i) - central).norm());
        size = std::max(size, central.norm());
      }
      INFO("impulse at " << impulse_time << " s, column " << i << ": largest difference " << largest << " of "
                         << size);
      CHECK(size > 0.1);
      CHECK(largest < 1e-6 * size);  // measured <= 1.5e-8 of the column
    }
  }
}

namespace {

// Two predictions made side by side read bit for bit as each made on its own, and the two
// differ (so the check could fail).
void check_side_by_side_as_alone(const std::vector<Eigen::Vector3d>& alone_a,
                                 const std::vector<Eigen::Vector3d>& alone_b,
                                 const std::vector<Eigen::Vector3d>& side_a,
                                 const std::vector<Eigen::Vector3d>& side_b) {
  REQUIRE(side_a.size() == alone_a.size());
  REQUIRE(side_b.size() == alone_b.size());
  bool same = true;
  for (std::size_t k = 0; k < alone_a.size(); ++k) {
    same = same && side_a[k] == alone_a[k] && side_b[k] == alone_b[k];
  }
  CHECK(same);
  CHECK(alone_a.back() != alone_b.back());
}

}  // namespace

TEST_CASE("two predictions side by side read bit for bit as each on its own, with a rotor and without",
          "[flight_model]") {
  const NominalInertia body = NominalInertia::of_tensor(Eigen::Vector3d(0.0017, 0.0042, 0.0054).asDiagonal());
  const Flight flight = kilohertz_flight();
  const Eigen::Vector3d w_a(0.3, 14.0, 0.5), w_b(0.3, 14.0 + 1e-6, 0.5);
  Eigen::VectorXd damping(2), jump(3);
  damping << 0.1, 0.3;  // a rotor that turns with the body at release
  jump << 0.4, -0.2, 0.3;
  struct Case {
    EffectModel model;
    Eigen::VectorXd theta;
    std::size_t ref;
  };
  const std::vector<Case> cases = {
      {EffectModel(Effect::internal_damping, body), damping, 0},  // one walk, paired
      {EffectModel(Effect::none, body), Eigen::VectorXd(), 0},    // one walk, shared steps
      {EffectModel(Effect::impulse, body, 0.6005), jump,
       flight.size() / 2},  // two walks: one after the other
  };
  for (const Case& c : cases) {
    CAPTURE(effect_name(c.model.effect), c.ref);
    std::vector<Eigen::Vector3d> alone_a, alone_b, side_a, side_b;
    predict_readings(c.model, flight, c.ref, w_a, c.theta, alone_a);
    predict_readings(c.model, flight, c.ref, w_b, c.theta, alone_b);
    predict_readings_pair(c.model, flight, c.ref, w_a, w_b, c.theta, side_a, side_b);
    check_side_by_side_as_alone(alone_a, alone_b, side_a, side_b);
  }
}

TEST_CASE("two predictions of different theta side by side read bit for bit as each on its own",
          "[flight_model]") {
  // predict_readings_two: a rotor's differenced theta columns, each lane with its own
  // body's terms; a rigid body with drag from the release sample (the three-rate lanes);
  // and two walks a prediction (one after the other).
  const NominalInertia body = NominalInertia::of_tensor(Eigen::Vector3d(0.0017, 0.0042, 0.0054).asDiagonal());
  const Flight flight = kilohertz_flight();
  const Eigen::Vector3d w_a(0.3, 14.0, 0.5), w_b(0.3, 14.0 + 1e-6, 0.5);
  Eigen::VectorXd damping_a(2), damping_b(2), drag_a(1), drag_b(1), jump_a(3), jump_b(3);
  damping_a << 0.1, 0.3;
  damping_b << 0.1, 0.3 + 1e-7;
  drag_a << 0.002;
  drag_b << 0.002 + 1e-9;
  jump_a << 0.4, -0.2, 0.3;
  jump_b << 0.4, -0.2 + 1e-7, 0.3;
  struct Case {
    EffectModel model;
    Eigen::VectorXd theta_a, theta_b;
    std::size_t ref;
  };
  const std::vector<Case> cases = {
      {EffectModel(Effect::internal_damping, body), damping_a, damping_b, 0},
      {EffectModel(Effect::aero_torque, body), drag_a, drag_b, 0},
      {EffectModel(Effect::impulse, body, 0.6005), jump_a, jump_b, flight.size() / 2},
  };
  for (const Case& c : cases) {
    CAPTURE(effect_name(c.model.effect), c.ref);
    std::vector<Eigen::Vector3d> alone_a, alone_b, side_a, side_b;
    predict_readings(c.model, flight, c.ref, w_a, c.theta_a, alone_a);
    predict_readings(c.model, flight, c.ref, w_b, c.theta_b, alone_b);
    predict_readings_two(c.model, flight, c.ref, w_a, c.theta_a, w_b, c.theta_b, side_a, side_b);
    check_side_by_side_as_alone(alone_a, alone_b, side_a, side_b);
  }
}
