// The body and sensor of one prediction (flight_model.hpp): the terms of (model, theta)
// made once, the rk4 steps of one walk or of two side by side in the lanes of a packed
// pair (each lane with its own body's terms where two predictions of different theta
// step together), and the sensor's reading of a state. Header-only: its steps are inlined
// into the prediction's loops (flight_model.cpp, reading_derivatives.cpp).
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/model_terms.hpp"
#include "diagnose/2_model/walk_layout.hpp"

namespace aloft::host::diagnose {

// A walk's state: the body rate, then the rotor's rate (damping only).
using DynamicsState = Eigen::Matrix<double, 6, 1>;

// A walk's state and, for the rigid body, the rate of change of its body rate there once
// known: that is both the first stage of the next rk4 step and the readings' slope at
// the sample (ReadingWalks::read_segment), so it is computed once where both need it
// (case00: 524 -> 517 M instructions, the same arithmetic, bit for bit).
struct Motion {
  DynamicsState x;
  Eigen::Vector3d rate =
      Eigen::Vector3d::Zero();  // rigid_rate(x.head<3>()), when rate_known; never for a rotor
  bool rate_known = false;
};

// Everything a flight needs from (model, theta), computed once per prediction.
class FlightDynamics {
 public:
  using Vec3 = Eigen::Vector3d;
  using Mat3 = Eigen::Matrix3d;
  using State = DynamicsState;

  FlightDynamics(const ModelTerms& terms, const Flight& flight)
      : inertia_(terms.inertia),
        drag_(terms.drag),
        rotor_(terms.rotor),
        rotor_rate_(terms.rotor_rate),
        has_jump_(terms.has_jump),
        time_factor_(terms.time_factor),
        jump_(terms.jump),
        momentum_(terms.momentum),
        has_momentum_(terms.momentum != Vec3::Zero()),
        bias_(terms.bias),
        scale_(terms.scale) {
    const Mat3 sensor_to_body = flight.sensor_to_body.toRotationMatrix();
    sensor_rotation_ =
        terms.misaligned ? Mat3(sensor_to_body * terms.misalignment.toRotationMatrix()) : sensor_to_body;
    // The shell carries the nominal tensor less the rotor, so that with the rotor locked
    // the body is the nominal one.
    shell_ = inertia_ - rotor_ * Mat3::Identity();
    shell_inverse_ = shell_.inverse();
    body_to_sensor_ = sensor_rotation_.transpose();
  }

  bool has_rotor() const { return rotor_ > 0.0; }
  bool has_drag() const { return drag_ != 0.0; }
  bool has_jump() const { return has_jump_; }
  bool has_momentum() const { return has_momentum_; }
  double time_factor() const { return time_factor_; }

  State rate(const State& x) const {
    const Vec3 w = x.head<3>();
    Vec3 torque = (shell_ * w).cross(w);
    if (drag_ != 0.0) torque -= drag_ * w.norm() * w;
    if (has_momentum()) torque += momentum_.cross(w);
    State dx;
    if (has_rotor()) {
      const Vec3 wr = x.tail<3>();
      const Vec3 coupling = rotor_rate_ * rotor_ * (wr - w);
      dx.head<3>() = shell_inverse_ * (torque + coupling);
      dx.tail<3>() = -w.cross(wr) - rotor_rate_ * (wr - w);
    } else {
      dx.head<3>() = shell_inverse_ * torque;
      dx.tail<3>().setZero();
    }
    return dx;
  }

  // Body rate alone, for every effect but the rotor's (the common, hot case).
  Vec3 rigid_rate(const Vec3& w) const {
    Vec3 torque = (shell_ * w).cross(w);
    if (drag_ != 0.0) torque -= drag_ * w.norm() * w;
    if (has_momentum()) torque += momentum_.cross(w);
    return shell_inverse_ * torque;
  }

  // One rk4 step; the rigid body's ends with its rate known (the next step's first stage).
  void rk4(Motion& m, double h) const {
    if (!has_rotor()) {
      const Vec3 w = m.x.head<3>();
      const Vec3 k1 = m.rate_known ? m.rate : rigid_rate(w);
      const Vec3 k2 = rigid_rate(w + 0.5 * h * k1);
      const Vec3 k3 = rigid_rate(w + 0.5 * h * k2);
      const Vec3 k4 = rigid_rate(w + h * k3);
      m.x.head<3>() = w + (h / 6.0) * (k1 + 2.0 * (k2 + k3) + k4);
      m.rate = rigid_rate(m.x.head<3>());
      m.rate_known = true;
      return;
    }
    // The rotor's six rates as rk4_pair's arithmetic in one scalar lane: Eigen's
    // six-vector code summed the same terms in the same order at about twice the
    // instructions (case00: 449.6 -> 437.5 M in all).
    LanesOf<double, 6> w;
    for (std::size_t i = 0; i < 6; ++i) w[i] = m.x(static_cast<Eigen::Index>(i));
    const LanesOf<double, 6> next = rk4_lanes(w, rates(w), h);
    for (std::size_t i = 0; i < 6; ++i) m.x(static_cast<Eigen::Index>(i)) = next[i];
  }

  // Two states one rk4 step each, every component in the two lanes of a packed pair: two
  // independent chains of dependent operations run side by side instead of one after the
  // other. The arithmetic is rk4's, term by term in the order Eigen evaluates rate()'s
  // expressions, so each state ends bit for bit where rk4 would take it. N = 3: the rigid
  // body's rate alone (its first stage the known rate, and the rate at the end left known,
  // as rk4 does); N = 6: with the rotor's.
  template <class L, std::size_t N>
  using LanesOf = std::array<L, N>;
  template <std::size_t N>
  using Lanes = LanesOf<Eigen::Array2d, N>;

  // One rk4 step of the lanes w (a packed pair, or one scalar lane) whose first stage is k1.
  template <class L, std::size_t N>
  [[gnu::always_inline]] LanesOf<L, N> rk4_lanes(const LanesOf<L, N>& w, const LanesOf<L, N>& k1,
                                                 const L& h) const {
    return rk4_lanes_with(*this, w, k1, h);
  }
  template <class T, class L, std::size_t N>
  [[gnu::always_inline]] static LanesOf<L, N> rk4_lanes_with(const T& t, const LanesOf<L, N>& w,
                                                             const LanesOf<L, N>& k1, const L& h) {
    const auto along = [](const LanesOf<L, N>& a, const L& s, const LanesOf<L, N>& k) {
      LanesOf<L, N> out;
      for (std::size_t i = 0; i < N; ++i) out[i] = a[i] + s * k[i];
      return out;
    };
    const L half = 0.5 * h;
    const LanesOf<L, N> k2 = rates_with(t, along(w, half, k1));
    const LanesOf<L, N> k3 = rates_with(t, along(w, half, k2));
    const LanesOf<L, N> k4 = rates_with(t, along(w, h, k3));
    const L sixth = h / 6.0;
    LanesOf<L, N> next;
    for (std::size_t i = 0; i < N; ++i) next[i] = w[i] + sixth * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
    return next;
  }

  template <std::size_t N>
  [[gnu::always_inline]] void rk4_pair(Motion& mx, double hx, Motion& my, double hy) const {
    rk4_pair_with<N>(*this, mx, hx, my, hy);
  }
  template <std::size_t N, class T>
  [[gnu::always_inline]] static void rk4_pair_with(const T& t, Motion& mx, double hx, Motion& my, double hy) {
    State& x = mx.x;
    State& y = my.x;
    Lanes<N> w;
    for (std::size_t i = 0; i < N; ++i)
      w[i] = Eigen::Array2d(x(static_cast<Eigen::Index>(i)), y(static_cast<Eigen::Index>(i)));
    const Eigen::Array2d h(hx, hy);
    const Lanes<N> next = rk4_lanes_with(t, w, first_stage_with(t, mx, my, w), h);
    for (std::size_t i = 0; i < N; ++i) {
      x(static_cast<Eigen::Index>(i)) = next[i](0);
      y(static_cast<Eigen::Index>(i)) = next[i](1);
    }
    if constexpr (N == 3) {
      const Lanes<N> end = rates_with(t, next);
      for (std::size_t i = 0; i < N; ++i) {
        mx.rate(static_cast<Eigen::Index>(i)) = end[i](0);
        my.rate(static_cast<Eigen::Index>(i)) = end[i](1);
      }
      mx.rate_known = my.rate_known = true;
    }
  }

  // rk4_pair's first stage: the known rates of both states, else rates() of both.
  template <class T, std::size_t N>
  [[gnu::always_inline]] static Lanes<N> first_stage_with(const T& t, const Motion& mx, const Motion& my,
                                                          const Lanes<N>& w) {
    if constexpr (N == 3) {
      if (mx.rate_known && my.rate_known) {
        Lanes<N> k1;
        for (std::size_t i = 0; i < N; ++i) {
          const Eigen::Index c = static_cast<Eigen::Index>(i);
          k1[i] = Eigen::Array2d(mx.rate(c), my.rate(c));
        }
        return k1;
      }
    }
    return rates_with(t, w);
  }

  // A 3x3 matrix times a vector as Eigen's fixed-size product sums it: rows 0 and 1 as a
  // packet, left to right; row 2 on its own, the last two terms first.
  template <class M, class L>
  [[gnu::always_inline]] static LanesOf<L, 3> times(const M& m, const L& v0, const L& v1, const L& v2) {
    return {m(0, 0) * v0 + m(0, 1) * v1 + m(0, 2) * v2, m(1, 0) * v0 + m(1, 1) * v1 + m(1, 2) * v2,
            m(2, 0) * v0 + (m(2, 1) * v1 + m(2, 2) * v2)};
  }
  template <class L>
  static LanesOf<L, 3> cross(const L* a, const L* b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }
  static double root(double v) { return std::sqrt(v); }
  static Eigen::Array2d root(const Eigen::Array2d& v) { return v.sqrt(); }
  template <class L>
  static L every_lane(double v) {
    if constexpr (std::is_same_v<L, double>) {
      return v;
    } else {
      return L::Constant(v);
    }
  }
  template <class L>
  static L every_lane(const Eigen::Array2d& v) {  // each lane's own already
    return v;
  }

  // rate() (N = 6) or rigid_rate() (N = 3) of every lane.
  template <class L, std::size_t N>
  [[gnu::always_inline]] LanesOf<L, N> rates(const LanesOf<L, N>& x) const {
    return rates_with(*this, x);
  }
  // The same with the terms of `t`: this body's (a number for every lane), or LaneTerms
  // (each lane its own body), the same arithmetic either way.
  template <class T, class L, std::size_t N>
  [[gnu::always_inline]] static LanesOf<L, N> rates_with(const T& t, const LanesOf<L, N>& x) {
    const LanesOf<L, 3> m = times(t.shell_, x[0], x[1], x[2]);
    LanesOf<L, 3> torque = cross(m.data(), x.data());
    if (t.has_drag()) {
      const L speed = root(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
      for (std::size_t i = 0; i < 3; ++i) torque[i] -= t.drag_ * speed * x[i];
    }
    if (t.has_momentum()) {  // momentum × w, a constant vector's cross with every lane
      const L h[3] = {every_lane<L>(t.momentum_(0)), every_lane<L>(t.momentum_(1)),
                      every_lane<L>(t.momentum_(2))};
      const LanesOf<L, 3> gyroscopic = cross(h, x.data());
      for (std::size_t i = 0; i < 3; ++i) torque[i] += gyroscopic[i];
    }
    LanesOf<L, N> dx;
    if constexpr (N == 3) {
      dx = times(t.shell_inverse_, torque[0], torque[1], torque[2]);
    } else {
      const auto coupling_rate = t.rotor_rate_ * t.rotor_;
      LanesOf<L, 3> body;
      for (std::size_t i = 0; i < 3; ++i) body[i] = torque[i] + coupling_rate * (x[i + 3] - x[i]);
      const LanesOf<L, 3> spin = times(t.shell_inverse_, body[0], body[1], body[2]);
      const LanesOf<L, 3> turn = cross(x.data(), x.data() + 3);
      for (std::size_t i = 0; i < 3; ++i) {
        dx[i] = spin[i];
        dx[i + 3] = -turn[i] - t.rotor_rate_ * (x[i + 3] - x[i]);
      }
    }
    return dx;
  }

  // Integrates over [from, to] (either direction) in steps of at most kMaxStep.
  void advance(Motion& x, double from, double to) const {
    const int steps = steps_over(to - from);
    advance(x, steps, step_of(to - from, steps));
  }
  void advance(Motion& x, int steps, double h) const {
    for (int i = 0; i < steps; ++i) rk4(x, h);
  }

  // advance() of two independent states, paired (rk4_pair) while both have steps to go:
  // each state gets exactly the steps advance() would give it.
  void advance_pair(Motion& x, int x_steps, double hx, Motion& y, int y_steps, double hy) const {
    const int both = std::min(x_steps, y_steps);
    for (int i = 0; i < both; ++i) {
      if (has_rotor()) {
        rk4_pair<6>(x, hx, y, hy);
      } else {
        rk4_pair<3>(x, hx, y, hy);
      }
    }
    for (int i = both; i < x_steps; ++i) rk4(x, hx);
    for (int i = both; i < y_steps; ++i) rk4(y, hy);
  }

  // The impulse changes L by I_nom dw; forwards adds it, backwards takes it away.
  void apply_jump(Motion& m, double sign) const {
    m.x.head<3>() += sign * (shell_inverse_ * (nominal_impulse_scale_ * jump_));
    m.rate_known = false;
  }
  void set_impulse_scale(const Mat3& nominal_tensor) { nominal_impulse_scale_ = nominal_tensor; }

  Vec3 reading(const State& x) const { return scale_.cwiseProduct(body_to_sensor_ * x.head<3>()) + bias_; }
  // The body rate that reads as `reading` (the sensor model backwards).
  Vec3 rate_of_reading(const Vec3& reading) const {
    return body_to_sensor_.transpose() * (reading - bias_).cwiseQuotient(scale_);
  }
  const Mat3& body_to_sensor() const { return body_to_sensor_; }
  const Vec3& scale() const { return scale_; }
  const Vec3& bias() const { return bias_; }
  const Mat3& shell_inverse() const { return shell_inverse_; }
  // The reading's change for a change dw of the body rate (the sensor without its bias).
  Vec3 sensor_map(const Vec3& dw) const { return scale_.cwiseProduct(body_to_sensor_ * dw); }

  // d w / dt, the body rate's part of rate() (rigid_rate() without a rotor).
  Vec3 body_rate_derivative(const Motion& m) const {
    if (m.rate_known) return m.rate;
    return has_rotor() ? Vec3(rate(m.x).head<3>()) : rigid_rate(m.x.head<3>());
  }

  // Two bodies' terms, each in its own lane of a packed pair: what rates_with() reads
  // where two predictions of different theta step side by side (predict_readings_two).
  // Both must have the same kind of terms (drag, momentum and rotor each in both or in
  // neither), so that each lane does the arithmetic its body's rk4 does.
  struct LaneTerms {
    struct Matrix {
      std::array<Eigen::Array2d, 9> e;
      const Eigen::Array2d& operator()(int i, int j) const { return e[static_cast<std::size_t>(3 * i + j)]; }
    };
    struct Vector {
      std::array<Eigen::Array2d, 3> e;
      const Eigen::Array2d& operator()(int i) const { return e[static_cast<std::size_t>(i)]; }
    };
    Matrix shell_, shell_inverse_;
    Eigen::Array2d drag_, rotor_, rotor_rate_;
    Vector momentum_;
    bool drag = false, momentum = false, rotor = false;

    bool has_drag() const { return drag; }
    bool has_momentum() const { return momentum; }
  };
  static bool same_kind(const FlightDynamics& a, const FlightDynamics& b) {
    return a.has_drag() == b.has_drag() && a.has_momentum() == b.has_momentum() &&
           a.has_rotor() == b.has_rotor();
  }
  static LaneTerms lane_terms(const FlightDynamics& a, const FlightDynamics& b) {
    LaneTerms t;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const std::size_t e = static_cast<std::size_t>(3 * i + j);
        t.shell_.e[e] = Eigen::Array2d(a.shell_(i, j), b.shell_(i, j));
        t.shell_inverse_.e[e] = Eigen::Array2d(a.shell_inverse_(i, j), b.shell_inverse_(i, j));
      }
      t.momentum_.e[static_cast<std::size_t>(i)] = Eigen::Array2d(a.momentum_(i), b.momentum_(i));
    }
    t.drag_ = Eigen::Array2d(a.drag_, b.drag_);
    t.rotor_ = Eigen::Array2d(a.rotor_, b.rotor_);
    t.rotor_rate_ = Eigen::Array2d(a.rotor_rate_, b.rotor_rate_);
    t.drag = a.has_drag();
    t.momentum = a.has_momentum();
    t.rotor = a.has_rotor();
    return t;
  }
  // advance_pair() of x under body `a` and y under body `b` (same_kind), their terms
  // `lanes` (lane_terms(a, b)): each state gets exactly the steps a.advance() and
  // b.advance() would give it.
  static void advance_two(const LaneTerms& lanes, const FlightDynamics& a, Motion& x, int x_steps, double hx,
                          const FlightDynamics& b, Motion& y, int y_steps, double hy) {
    const int both = std::min(x_steps, y_steps);
    for (int i = 0; i < both; ++i) {
      if (lanes.rotor) {
        rk4_pair_with<6>(lanes, x, hx, y, hy);
      } else {
        rk4_pair_with<3>(lanes, x, hx, y, hy);
      }
    }
    for (int i = both; i < x_steps; ++i) a.rk4(x, hx);
    for (int i = both; i < y_steps; ++i) b.rk4(y, hy);
  }

 private:
  Mat3 inertia_;
  Mat3 sensor_rotation_;
  Mat3 shell_;
  Mat3 shell_inverse_;
  Mat3 body_to_sensor_;
  Mat3 nominal_impulse_scale_ = Mat3::Identity();
  double drag_ = 0.0;
  double rotor_ = 0.0;
  double rotor_rate_ = 0.0;
  bool has_jump_ = false;
  double time_factor_ = 1.0;
  Vec3 jump_ = Vec3::Zero();
  Vec3 momentum_ = Vec3::Zero();
  bool has_momentum_ = false;
  Vec3 bias_ = Vec3::Zero();
  Vec3 scale_ = Vec3::Ones();
};

}  // namespace aloft::host::diagnose
