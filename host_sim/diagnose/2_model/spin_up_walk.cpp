#include "diagnose/2_model/spin_up_walk.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "diagnose/2_model/walk_layout.hpp"

namespace aloft::host::diagnose {
namespace {

using Vec3 = Eigen::Vector3d;
using State = DynamicsState;

// The body and the rotor's profile on the walk's clock (the reference's time plus true
// time elapsed: recorded time times the clock factor).
struct SpinUpBody {
  const FlightDynamics& dynamics;
  Vec3 final_momentum;
  SpinUpProfile profile;  // its start on the walk's clock

  State rate(double t, const State& x, bool running) const {
    State dx = dynamics.rate(x);
    if (!running) return dx;
    const double u = std::max(t - profile.start_s, 0.0);
    const Vec3 h = profile.level(u) * final_momentum, h_rate = profile.slope(u) * final_momentum;
    dx.head<3>() += dynamics.shell_inverse() * (h.cross(Vec3(x.head<3>())) - h_rate);
    return dx;
  }
  // One RK4 step of signed length h from t; the motor's side from the step's middle.
  void step(double t, double h, State& x) const {
    const bool running = t + 0.5 * h > profile.start_s;
    const State k1 = rate(t, x, running);
    const State k2 = rate(t + 0.5 * h, x + 0.5 * h * k1, running);
    const State k3 = rate(t + 0.5 * h, x + 0.5 * h * k2, running);
    const State k4 = rate(t + h, x + h * k3, running);
    x += (h / 6.0) * (k1 + 2.0 * (k2 + k3) + k4);
  }
  // From t to u (either way) in steps no longer than kMaxStep, or than half the loop's time
  // constant in its transients (in_transient).
  void advance(double t, double u, State& x) const {
    if (t == u) return;
    const double longest = in_transient(0.5 * (t + u)) ? 0.5 * profile.time_constant_s : kMaxStep;
    const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(u - t) / longest - 1e-9)));
    const double h = (u - t) / steps;
    for (int i = 0; i < steps; ++i) step(t + i * h, h, x);
  }
  // The loop's transients, where ds/dt moves on the scale of tau: kTransientSpan time
  // constants after the start and after the ramp's end (the start twice for a step). Walked
  // in finer steps only where tau is shorter than two of the walk's longest steps: RK4
  // across one such step misses the torque's rise (the generator's ramp, walked with
  // tau = 1 ns, came out 2.6e-3 rad/s off over a second in 1 ms steps, 1.2e-7 with these:
  // tests/diagnose/test_spin_up_sessions.cpp).
  static constexpr double kTransientSpan = 10.0;
  bool fast() const { return profile.time_constant_s < 2.0 * kMaxStep; }
  std::array<double, 2> transient_starts() const {
    return {profile.start_s, profile.start_s + profile.rise_s};
  }
  bool in_transient(double t) const {
    if (!fast()) return false;
    for (double from : transient_starts()) {
      if (t > from && t < from + kTransientSpan * profile.time_constant_s) return true;
    }
    return false;
  }
};

// From t to u, stopping where they lie strictly between: at the motor's start and the end of
// its set-point's ramp (the same instant for a step), at the ends of the loop's fast
// transients after them, and at an impulse's instant (applied forwards with +1, backwards
// with -1), each once.
void advance_across(const SpinUpBody& body, double t, double u, double jump_time, bool has_jump, Motion& m) {
  std::vector<double> stops;
  const auto between = [&](double s) { return (s - t) * (u - s) > 0.0; };
  for (double from : body.transient_starts()) {
    if (between(from)) stops.push_back(from);
    const double settled = from + SpinUpBody::kTransientSpan * body.profile.time_constant_s;
    if (body.fast() && between(settled)) stops.push_back(settled);
  }
  if (has_jump && between(jump_time)) stops.push_back(jump_time);
  std::sort(stops.begin(), stops.end(), [&](double a, double b) { return (a - b) * (u - t) < 0.0; });
  stops.erase(std::unique(stops.begin(), stops.end()), stops.end());
  double at = t;
  for (double s : stops) {
    body.advance(at, s, m.x);
    if (has_jump && s == jump_time) body.dynamics.apply_jump(m, u > t ? 1.0 : -1.0);
    at = s;
  }
  body.advance(at, u, m.x);
}

}  // namespace

void predict_spin_up_readings(const FlightDynamics& dynamics, const ModelTerms& terms, const Flight& flight,
                              std::size_t ref, const Vec3& omega_ref, double jump_time,
                              std::vector<Vec3>& readings, ReadSamples read) {
  const std::size_t n = flight.size();
  readings.resize(n);
  if (n == 0) return;
  const double t_ref = flight.time_s[ref], factor = dynamics.time_factor();
  const auto walk_time = [&](double t) { return t_ref + (t - t_ref) * factor; };
  SpinUpProfile profile = terms.spin_up_profile;
  profile.start_s = walk_time(flight.time_s.front() + profile.start_s);
  const SpinUpBody body{dynamics, terms.spin_up_momentum, profile};
  Motion start;
  start.x.head<3>() = omega_ref;
  start.x.tail<3>() = omega_ref;  // a damping rotor co-rotating at the reference
  readings[ref] = dynamics.reading(start.x);
  const bool jumps = dynamics.has_jump();
  Motion m = start;
  for (std::size_t k = ref + 1; k < n; ++k) {
    advance_across(body, walk_time(flight.time_s[k - 1]), walk_time(flight.time_s[k]), jump_time, jumps, m);
    if (read.wanted(k)) readings[k] = dynamics.reading(m.x);
  }
  m = start;
  for (std::size_t k = ref; k-- > 0;) {
    advance_across(body, walk_time(flight.time_s[k + 1]), walk_time(flight.time_s[k]), jump_time, jumps, m);
    if (read.wanted(k)) readings[k] = dynamics.reading(m.x);
  }
}

}  // namespace aloft::host::diagnose
