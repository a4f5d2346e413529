#include "diagnose/2_model/flight_model.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>
#include <utility>

#include "diagnose/2_model/effect_descriptor.hpp"
#include "diagnose/2_model/walk_layout.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using State = Eigen::Matrix<double, 6, 1>;  // body rate, then the rotor's rate (damping only)

// Samples this close share one step, the readings between interpolated (ReadingWalks):
// 1 kHz data takes one step every 5 samples instead of one a sample (case00: 2.10 G
// instructions -> 1.33 G). Not for a model with a rotor: the internal damping fits reach
// coupling rates of ~200 /s, where a 5 ms step misjudges the rotor and the fitted rotor
// moved (practice2/A02 then named internal_damping instead of inertia_axes).
constexpr double kMaxSegment = kMaxStep;

// The slice of theta that belongs to `effect` (empty when it is not in the model).
Eigen::VectorXd slice_of(const EffectModel& model, const Eigen::VectorXd& theta, Effect effect) {
  const int offset = theta_offset(model, effect);
  if (offset < 0) return Eigen::VectorXd();
  return theta.segment(offset, effect_parameter_count(effect));
}

// A walk's state and, for the rigid body, the rate of change of its body rate there once
// known: that is both the first stage of the next rk4 step and the readings' slope at
// the sample (ReadingWalks::read_segment), so it is computed once where both need it
// (case00: 524 -> 517 M instructions, the same arithmetic, bit for bit).
struct Motion {
  State x;
  Vec3 rate = Vec3::Zero();  // rigid_rate(x.head<3>()), when rate_known; never for a rotor
  bool rate_known = false;
};

// Everything a flight needs from (model, theta), computed once per prediction.
class FlightDynamics {
 public:
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

// The walks of predict_readings from the reference sample outwards, one segment of
// their layout (walk_layout.hpp) at a time.
class ReadingWalks {
 public:
  ReadingWalks(const FlightDynamics& dynamics, double jump_time, std::vector<Vec3>& readings,
               const std::vector<HermiteWeights>& weights, Vec3* rate_at_impulse, ReadSamples read)
      : d_(dynamics),
        readings_(readings),
        weights_(weights),
        rate_at_impulse_(rate_at_impulse),
        t_jump_(jump_time),
        read_(read) {}

  // A walk at its latest sample: the state there and, when the segment that ended there
  // interpolated, the readings' rate of change there (the next segment starts with it).
  struct Walk {
    Motion m;
    std::size_t at = 0;
    bool slope_known = false;
    Vec3 slope = Vec3::Zero();  // d reading / dt, without the segment's length
  };

  // One segment of a walk, on its own.
  void step(Walk& walk, const WalkSegment& seg) const {
    Motion& x = walk.m;
    const double a = seg.a, b = seg.b;
    if (seg.crosses) {
      const bool forwards = seg.to > seg.from;
      // Forwards: to the impulse, add it, on if it is before b. Backwards: to the impulse
      // if it is before a, take it away, on.
      if (forwards) {
        d_.advance(x, a, t_jump_);
        if (rate_at_impulse_ != nullptr) *rate_at_impulse_ = x.x.head<3>();
        d_.apply_jump(x, 1.0);
        if (b > t_jump_) d_.advance(x, t_jump_, b);
      } else {
        if (a > t_jump_) d_.advance(x, a, t_jump_);
        if (rate_at_impulse_ != nullptr) *rate_at_impulse_ = x.x.head<3>();
        d_.apply_jump(x, -1.0);
        d_.advance(x, t_jump_, b);
      }
      readings_[seg.to] = d_.reading(x.x);
      walk.at = seg.to;
      walk.slope_known = false;
      return;
    }
    const Motion start = x;
    d_.advance(x, seg.steps, seg.h);
    read_segment(start, walk, seg);
  }

  // The readings of a segment integrated from `x_from` at sample `from` to `x_to` at
  // `to`: the end's own, and those between by cubic Hermite interpolation of the rate
  // (its error, h^4 |d4w/dt4| / 384, is 1e-6 rad/s for a 15 rad/s tumble over 5 ms),
  // made on the readings: they are affine in the rate, and the basis weights of the two
  // ends sum to one, so interpolating the readings with the rate's derivatives mapped
  // as the rate is (sensor_map) is interpolating the rate.
  // `walk` has been integrated to `to` from `x_from`, its state at walk.at.
  void read_segment(const Motion& x_from, Walk& walk, const WalkSegment& seg) const {
    const std::size_t from = seg.from, to = seg.to;
    walk.at = to;
    readings_[to] = d_.reading(walk.m.x);
    if (to == from + 1 || from == to + 1) {
      walk.slope_known = false;
      return;
    }
    const Vec3 slope_from = walk.slope_known ? walk.slope : d_.sensor_map(d_.body_rate_derivative(x_from));
    walk.slope = d_.sensor_map(d_.body_rate_derivative(walk.m));
    walk.slope_known = true;
    const double h = seg.b - seg.a;
    const Vec3 r0 = readings_[from], r1 = readings_[to];
    const Vec3 g0 = slope_from * h, g1 = walk.slope * h;
    const std::size_t lo = std::min(from, to), hi = std::max(from, to);
    if (!wanted_between(lo, hi)) {
      for (std::size_t k = lo + 1; k < hi; ++k) readings_[k].setZero();
      return;
    }
    const HermiteWeights* w = &weights_[seg.weights];
    for (std::size_t k = lo + 1; k < hi; ++k, ++w) {
      readings_[k] = (*w)[0] * r0 + (*w)[1] * r1 + (*w)[2] * g0 + (*w)[3] * g1;
    }
  }

  // Some sample strictly between lo and hi is wanted (read_): a segment lies nearly always
  // wholly inside a fold's chunk or outside it, so it is interpolated whole or not at all.
  bool wanted_between(std::size_t lo, std::size_t hi) const {
    for (std::size_t k = lo + 1; k < hi; ++k) {
      if (read_.wanted(k)) return true;
    }
    return false;
  }

 private:
  const FlightDynamics& d_;
  std::vector<Vec3>& readings_;
  const std::vector<HermiteWeights>& weights_;
  Vec3* rate_at_impulse_ = nullptr;  // where the walk that meets the impulse reaches it
  double t_jump_ = 0.0;
  ReadSamples read_;  // the samples between steps worth interpolating
};

}  // namespace

std::size_t reference_index(Effect effect, const Flight& flight) {
  if (describe(effect).starts_at_release || flight.size() == 0) return 0;
  return flight.size() / 2;
}

Eigen::Vector3d body_rate_of_reading(const Flight& flight, const Eigen::Vector3d& reading) {
  return flight.sensor_to_body * reading;
}

std::size_t compound_reference_index(const EffectModel& model, const Flight& flight) {
  for (Effect e : model_effects(model)) {
    if (describe(e).starts_at_release) return reference_index(e, flight);
  }
  return reference_index(Effect::none, flight);
}

std::vector<Effect> model_effects(const EffectModel& model) {
  std::vector<Effect> effects;
  for (Effect e : model.base) {
    if (e != Effect::none) effects.push_back(e);
  }
  if (model.effect != Effect::none) effects.push_back(model.effect);
  return effects;
}

int theta_offset(const EffectModel& model, Effect effect) {
  int offset = 0;
  for (Effect e : model_effects(model)) {
    if (e == effect) return offset;
    offset += effect_parameter_count(e);
  }
  return -1;
}

bool has_searched_time(const EffectModel& model) {
  for (Effect e : model_effects(model)) {
    if (describe(e).searched_parameters > 0) return true;
  }
  return false;
}

int model_parameter_count(const EffectModel& model) {
  int count = 0;
  for (Effect e : model_effects(model)) count += effect_parameter_count(e);
  return count;
}

ModelTerms model_terms(const EffectModel& model, const Eigen::VectorXd& theta) {
  ModelTerms terms(model.nominal);
  const std::vector<Effect> effects = model_effects(model);
  for (bool first : {true, false}) {
    for (Effect e : effects) {
      const EffectDescriptor& d = describe(e);
      if (d.sets_tensor == first) d.hooks.apply(slice_of(model, theta, e), model.nominal, terms);
    }
  }
  return terms;
}

Eigen::Vector3d body_rate_for_reading(const EffectModel& model, const Flight& flight,
                                      const Eigen::VectorXd& theta, const Eigen::Vector3d& reading) {
  // The sensor model backwards: take the bias off, undo the scale, then the rotation.
  const ModelTerms terms = model_terms(model, theta);
  Vec3 w = reading - terms.bias;
  w = w.cwiseQuotient(terms.scale);
  if (terms.misaligned) w = terms.misalignment * w;
  return flight.sensor_to_body * w;
}

namespace {

WalkLayoutKey layout_key(const EffectModel& model, const Flight& flight, std::size_t ref,
                         SampleStepping stepping, const FlightDynamics& dynamics) {
  WalkLayoutKey key;
  key.ref = ref;
  key.max_segment = stepping == SampleStepping::shared_steps ? kMaxSegment : 0.0;
  key.single_samples = dynamics.has_rotor();
  key.has_jump = dynamics.has_jump();
  key.time_factor = dynamics.time_factor();
  const double t_ref = flight.time_s[ref];
  key.jump_time = key.has_jump ? t_ref + (model.impulse_time_s - t_ref) * key.time_factor : 0.0;
  return key;
}

Motion start_at(const Eigen::Vector3d& omega_ref) {
  Motion start;
  start.x.head<3>() = omega_ref;
  start.x.tail<3>() = omega_ref;  // rotor co-rotating at the reference (damping only)
  return start;
}

// Two independent walks, each through its own segments into its own readings: while both
// have segments to go, they step together (advance_pair(a, a_steps, a_h, b, b_steps, b_h):
// FlightDynamics::advance_pair or advance_two) where neither crosses the impulse.
template <class AdvancePair>
void walk_together(const AdvancePair& advance_pair, const ReadingWalks& walks_a, ReadingWalks::Walk& a,
                   const std::vector<WalkSegment>& segments_a, const ReadingWalks& walks_b,
                   ReadingWalks::Walk& b, const std::vector<WalkSegment>& segments_b) {
  const std::size_t both = std::min(segments_a.size(), segments_b.size());
  for (std::size_t i = 0; i < both; ++i) {
    const WalkSegment &u = segments_a[i], &d = segments_b[i];
    if (!u.crosses && !d.crosses) {
      const Motion a_from = a.m, b_from = b.m;
      advance_pair(a.m, u.steps, u.h, b.m, d.steps, d.h);
      walks_a.read_segment(a_from, a, u);
      walks_b.read_segment(b_from, b, d);
    } else {
      walks_a.step(a, u);
      walks_b.step(b, d);
    }
  }
  for (std::size_t i = both; i < segments_a.size(); ++i) walks_a.step(a, segments_a[i]);
  for (std::size_t i = both; i < segments_b.size(); ++i) walks_b.step(b, segments_b[i]);
}

// FlightDynamics::advance_pair of one body, for walk_together.
auto paired_steps(const FlightDynamics& dynamics) {
  return [&dynamics](Motion& x, int x_steps, double hx, Motion& y, int y_steps, double hy) {
    dynamics.advance_pair(x, x_steps, hx, y, y_steps, hy);
  };
}

}  // namespace

void predict_readings(const EffectModel& model, const Flight& flight, std::size_t ref,
                      const Eigen::Vector3d& omega_ref, const Eigen::VectorXd& theta,
                      std::vector<Eigen::Vector3d>& readings, SampleStepping stepping,
                      Eigen::Vector3d* rate_at_impulse, ReadSamples read) {
  const std::size_t n = flight.size();
  readings.resize(n);
  if (n == 0) return;
  FlightDynamics dynamics(model_terms(model, theta), flight);
  dynamics.set_impulse_scale(model.nominal.tensor);
  const WalkLayoutKey key = layout_key(model, flight, ref, stepping, dynamics);
  const WalkLayout& layout = walk_layout(flight.time_s, key);
  const ReadingWalks walks(dynamics, key.jump_time, readings, layout.weights, rate_at_impulse, read);
  const Motion start = start_at(omega_ref);
  readings[ref] = dynamics.reading(start.x);
  // Forwards from the reference and backwards from it, independent of each other.
  ReadingWalks::Walk up{start, ref}, down{start, ref};
  walk_together(paired_steps(dynamics), walks, up, layout.up, walks, down, layout.down);
}

namespace {

// predict_readings of (omega_a, theta_a), then of (omega_b, theta_b): where the two
// cannot step side by side.
void predict_one_after_the_other(const EffectModel& model, const Flight& flight, std::size_t ref,
                                 const Eigen::Vector3d& omega_a, const Eigen::VectorXd& theta_a,
                                 const Eigen::Vector3d& omega_b, const Eigen::VectorXd& theta_b,
                                 std::vector<Eigen::Vector3d>& readings_a,
                                 std::vector<Eigen::Vector3d>& readings_b, ReadSamples read) {
  predict_readings(model, flight, ref, omega_a, theta_a, readings_a, SampleStepping::shared_steps, nullptr,
                   read);
  predict_readings(model, flight, ref, omega_b, theta_b, readings_b, SampleStepping::shared_steps, nullptr,
                   read);
}

// The one walk of each of two predictions from `ref`, the first or last sample (the
// layout's other direction has no segments), side by side: advance_pair steps them
// together (walk_together), each in its own body's terms.
template <class AdvancePair>
void one_walks_side_by_side(const AdvancePair& advance_pair, const FlightDynamics& dynamics_a,
                            const FlightDynamics& dynamics_b, const WalkLayout& layout, double jump_time,
                            std::size_t ref, const Eigen::Vector3d& omega_a, const Eigen::Vector3d& omega_b,
                            std::vector<Eigen::Vector3d>& readings_a,
                            std::vector<Eigen::Vector3d>& readings_b, std::size_t n, ReadSamples read) {
  readings_a.resize(n);
  readings_b.resize(n);
  const ReadingWalks walks_a(dynamics_a, jump_time, readings_a, layout.weights, nullptr, read),
      walks_b(dynamics_b, jump_time, readings_b, layout.weights, nullptr, read);
  const Motion start_a = start_at(omega_a), start_b = start_at(omega_b);
  readings_a[ref] = dynamics_a.reading(start_a.x);
  readings_b[ref] = dynamics_b.reading(start_b.x);
  ReadingWalks::Walk a{start_a, ref}, b{start_b, ref};
  const std::vector<WalkSegment>& segments = layout.up.empty() ? layout.down : layout.up;
  walk_together(advance_pair, walks_a, a, segments, walks_b, b, segments);
}

}  // namespace

void predict_readings_pair(const EffectModel& model, const Flight& flight, std::size_t ref,
                           const Eigen::Vector3d& omega_a, const Eigen::Vector3d& omega_b,
                           const Eigen::VectorXd& theta, std::vector<Eigen::Vector3d>& readings_a,
                           std::vector<Eigen::Vector3d>& readings_b, ReadSamples read) {
  const std::size_t n = flight.size();
  if (n == 0 || (ref != 0 && ref + 1 != n)) {
    predict_one_after_the_other(model, flight, ref, omega_a, theta, omega_b, theta, readings_a, readings_b,
                                read);
    return;
  }
  FlightDynamics dynamics(model_terms(model, theta), flight);
  dynamics.set_impulse_scale(model.nominal.tensor);
  const WalkLayoutKey key = layout_key(model, flight, ref, SampleStepping::shared_steps, dynamics);
  one_walks_side_by_side(paired_steps(dynamics), dynamics, dynamics, walk_layout(flight.time_s, key),
                         key.jump_time, ref, omega_a, omega_b, readings_a, readings_b, n, read);
}

void predict_readings_two(const EffectModel& model, const Flight& flight, std::size_t ref,
                          const Eigen::Vector3d& omega_a, const Eigen::VectorXd& theta_a,
                          const Eigen::Vector3d& omega_b, const Eigen::VectorXd& theta_b,
                          std::vector<Eigen::Vector3d>& readings_a, std::vector<Eigen::Vector3d>& readings_b,
                          ReadSamples read) {
  if (theta_a.size() == theta_b.size() && (theta_a.array() == theta_b.array()).all()) {
    predict_readings_pair(model, flight, ref, omega_a, omega_b, theta_a, readings_a, readings_b, read);
    return;
  }
  const std::size_t n = flight.size();
  FlightDynamics dynamics_a(model_terms(model, theta_a), flight),
      dynamics_b(model_terms(model, theta_b), flight);
  dynamics_a.set_impulse_scale(model.nominal.tensor);
  dynamics_b.set_impulse_scale(model.nominal.tensor);
  const WalkLayoutKey key = layout_key(model, flight, ref, SampleStepping::shared_steps, dynamics_a);
  if (n == 0 || (ref != 0 && ref + 1 != n) || !FlightDynamics::same_kind(dynamics_a, dynamics_b) ||
      !(layout_key(model, flight, ref, SampleStepping::shared_steps, dynamics_b) == key)) {
    predict_one_after_the_other(model, flight, ref, omega_a, theta_a, omega_b, theta_b, readings_a,
                                readings_b, read);
    return;
  }
  // Each lane with its own body's terms.
  const FlightDynamics::LaneTerms lanes = FlightDynamics::lane_terms(dynamics_a, dynamics_b);
  const auto advance_two = [&](Motion& x, int x_steps, double hx, Motion& y, int y_steps, double hy) {
    FlightDynamics::advance_two(lanes, dynamics_a, x, x_steps, hx, dynamics_b, y, y_steps, hy);
  };
  one_walks_side_by_side(advance_two, dynamics_a, dynamics_b, walk_layout(flight.time_s, key), key.jump_time,
                         ref, omega_a, omega_b, readings_a, readings_b, n, read);
}

namespace {

// Step of the central differences of the terms along theta: the sensor terms are linear
// in theta or a quaternion exponential, whose O(h^2) error at 1e-5 is ~1e-10 relative, as
// is the rounding (eps / h); the columns they replace were forward differences of whole
// simulations, good to ~1e-7.
constexpr double kTermStep = 1e-5;

// The terms with theta moved by the step either way along parameter i.
struct NudgedTerms {
  double h;  // the step
  ModelTerms up, down;
};
NudgedTerms nudged_terms(const EffectModel& model, const Eigen::VectorXd& theta, Eigen::Index i) {
  const double h = kTermStep * std::max(1.0, std::abs(theta(i)));
  Eigen::VectorXd up = theta, down = theta;
  up(i) += h;
  down(i) -= h;
  return {h, model_terms(model, up), model_terms(model, down)};
}

// The rotation's terms other than the impulse's jump are the same.
bool same_motion_but_jump(const ModelTerms& a, const ModelTerms& b) {
  return a.inertia == b.inertia && a.drag == b.drag && a.rotor == b.rotor && a.rotor_rate == b.rotor_rate &&
         a.momentum == b.momentum && a.time_factor == b.time_factor;
}

bool same_sensor(const ModelTerms& a, const ModelTerms& b) {
  return a.scale == b.scale && a.bias == b.bias && a.misaligned == b.misaligned &&
         a.misalignment.coeffs() == b.misalignment.coeffs();
}

// Whether moving theta along direction i changes the sensor's terms and nothing else.
bool moves_sensor_only(const ModelTerms& up, const ModelTerms& down) {
  return same_motion_but_jump(up, down) && up.has_jump == down.has_jump && up.jump == down.jump &&
         up.misaligned == down.misaligned && !same_sensor(up, down);
}

}  // namespace

std::vector<char> sensor_directions(const EffectModel& model, const Eigen::VectorXd& theta) {
  std::vector<char> out(static_cast<std::size_t>(theta.size()), 0);
  for (Eigen::Index i = 0; i < theta.size(); ++i) {
    const NudgedTerms t = nudged_terms(model, theta, i);
    out[static_cast<std::size_t>(i)] = moves_sensor_only(t.up, t.down);
  }
  return out;
}

void sensor_reading_derivatives(const EffectModel& model, const Flight& flight, const Eigen::VectorXd& theta,
                                const std::vector<Eigen::Vector3d>& readings,
                                const std::vector<char>& directions, Eigen::MatrixXd& columns) {
  const std::size_t n = flight.size();
  const FlightDynamics at(model_terms(model, theta), flight);
  std::vector<Vec3> rates(n);
  for (std::size_t k = 0; k < n; ++k) rates[k] = at.rate_of_reading(readings[k]);
  for (Eigen::Index i = 0; i < theta.size(); ++i) {
    if (!directions[static_cast<std::size_t>(i)]) continue;
    const NudgedTerms t = nudged_terms(model, theta, i);
    const double h = t.h;
    const FlightDynamics a(t.up, flight), b(t.down, flight);
    // reading = scale (B w) + bias, differentiated with w held.
    const Mat3 d_sensor = (a.body_to_sensor() - b.body_to_sensor()) / (2.0 * h);
    const Vec3 d_scale = (a.scale() - b.scale()) / (2.0 * h), d_bias = (a.bias() - b.bias()) / (2.0 * h);
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3& w = rates[k];
      columns.block<3, 1>(static_cast<Eigen::Index>(3 * k), i) =
          d_scale.cwiseProduct(at.body_to_sensor() * w) + at.scale().cwiseProduct(d_sensor * w) + d_bias;
    }
  }
}

std::vector<char> impulse_directions(const EffectModel& model, const Eigen::VectorXd& theta) {
  std::vector<char> out(static_cast<std::size_t>(theta.size()), 0);
  for (Eigen::Index i = 0; i < theta.size(); ++i) {
    const NudgedTerms t = nudged_terms(model, theta, i);
    out[static_cast<std::size_t>(i)] = same_motion_but_jump(t.up, t.down) && t.up.has_jump &&
                                       t.down.has_jump && same_sensor(t.up, t.down) &&
                                       t.up.jump != t.down.jump;
  }
  return out;
}

void impulse_reading_derivatives(const EffectModel& model, const Flight& flight, std::size_t ref,
                                 const Eigen::VectorXd& theta, const Eigen::Matrix3d& impulse_rate_derivative,
                                 const std::vector<char>& directions, Eigen::MatrixXd& jacobian) {
  const std::size_t n = flight.size();
  const Eigen::Index rates = theta.size();
  const FlightDynamics at(model_terms(model, theta), flight);
  const double t_ref = flight.time_s[ref];
  const auto true_time = [&](double t) { return t_ref + (t - t_ref) * at.time_factor(); };
  const double t_jump = true_time(model.impulse_time_s);
  // The walk that meets the impulse adds it going forwards and takes it away going
  // backwards; past it, a change of the rate there is carried as a change of omega_ref
  // would be, by the flow map: d reading_k / d rate_at_impulse = G_k Phi_j^-1.
  const double sign = t_jump > t_ref ? 1.0 : -1.0;
  const Mat3 carried = impulse_rate_derivative.inverse() * at.shell_inverse() * model.nominal.tensor;
  // Each marked column's carried change, then each sample once for all of them: which
  // side of the impulse it is on, and its rate rows read once (case00 408.8 -> 407.1 M
  // instructions against a pass over the samples per column).
  std::vector<std::pair<Eigen::Index, Vec3>> marked;
  for (Eigen::Index i = 0; i < theta.size(); ++i) {
    if (!directions[static_cast<std::size_t>(i)]) continue;
    const NudgedTerms t = nudged_terms(model, theta, i);
    const Vec3 d_jump = (t.up.jump - t.down.jump) / (2.0 * t.h);
    marked.emplace_back(i, sign * (carried * d_jump));
  }
  for (std::size_t k = 0; k < n; ++k) {
    const double t = true_time(flight.time_s[k]);
    const bool past = sign > 0.0 ? t >= t_jump : t < t_jump;
    const Eigen::Index row = static_cast<Eigen::Index>(3 * k);
    for (const auto& [i, c] : marked) {
      if (past) {
        jacobian.block<3, 1>(row, i) = jacobian.block<3, 3>(row, rates) * c;
      } else {
        jacobian.block<3, 1>(row, i).setZero();
      }
    }
  }
}

EffectParameters effect_parameters(const EffectModel& model, const Eigen::VectorXd& theta) {
  return effect_parameters(model, theta, model.effect);
}

EffectParameters effect_parameters(const EffectModel& model, const Eigen::VectorXd& all_theta,
                                   Effect effect) {
  const Eigen::VectorXd theta = slice_of(model, all_theta, effect);
  if (theta.size() != effect_parameter_count(effect)) return EffectParameters();
  return describe(effect).hooks.parameters(theta, model.nominal, model.impulse_time_s);
}

}  // namespace aloft::host::diagnose
