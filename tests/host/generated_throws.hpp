// Generated IMU recordings of hand throws, for the release and landing tests: the truth
// (release and landing instants, the IMU's position) is known exactly, the sensor is not
// ideal. One recording holds the body, then throws (or drops) it several times:
//   - hold: the hand supports it (specific force g up) with a little tremor;
//   - swing: the hand applies force AND torque: the body is accelerated along an arc
//     (force up to 40 m/s² turning through 90° in the vertical plane) while its rate
//     grows from zero to the release rate; the force fades to zero at the release over a
//     few milliseconds (reaching zero with a finite slope, as contact breaks), the
//     torque either fades or stops there;
//   - flight: torque-free (Euler's equations, RK4 with the true tensor); gravity is not
//     sensed; a small drag-like force (≤ 0.3 m/s²) is;
//   - landing: a catch (force rising over 5–15 ms to 20–60 m/s², the rate fading out) or an
//     impact (1–2 ms to 200–1500 m/s², the rate thrown off), then held again.
// With `real_hand` (RecordingSpec) the throws are as the held-back real ones showed:
//   - the hand lets go over 2–30 ms with a slow tail: the force falls as x (0.25 + 0.75 x)
//     of its swing value, x the fraction of the let-go left, so its last milliseconds are
//     a few tenths of m/s² (the real throws: 15 m/s² to 3 m/s² over the last 20–30 ms);
//   - the hand's torque fades over the same span (the rate keeps changing until the end);
//   - the body rings after release and after a catch: one or two structural modes at
//     100–800 Hz along fixed body directions, decaying over 5–30 ms, up to 8 m/s² in
//     single samples.
// With `retouch` (RecordingSpec) a finger touches again as the body leaves, as in the one
// held-back real throw whose release came 14.9 ms early: after the let-go the hand's force
// is gone for 2-4 ms (the body flies free), then a finger pushes for 5-15 ms at 3-4 m/s²
// at the centre of mass (rising and falling over 1-3 ms each), with the torque of its
// contact point 1-2 radii of gyration off the centre; then the hand is gone.
// With `rotor` (RecordingSpec) the body carries a rotor whose speed the firmware logs
// (rotor_flight.hpp): J 0.3-1.2 % of the body's smallest moment about a random axis; in
// each spinning throw it starts from rest 0-60 ms after the release and spins up over
// 0.15-0.25 s (a ramp or a first-order rise) to ±300-1500 rad/s, holds that for
// 0.05-0.2 s (the pulse) and brakes to rest over 0.05-0.15 s; the flight lasts 0.15-0.35 s
// longer so that most of it is airborne, and is the gyrostat's, I ω̇ + ω × (I ω + h) = −ḣ.
// Every sample carries the speed as DShot telemetry gives it: a frame every 0.125-2 ms,
// 1-4 ms late, 9 significant bits, held between frames.
// TrueFlight::release_s is where the hand's force reaches zero for good (after the
// re-touch); `force_below_1_s` is where
// it last fell below 1 m/s² (a tenth of g), which no accelerometer tells from its noise
// and the air's drag: a release dated between the two is not early.
// The accelerometer at r reads R^T f + w_dot x r + w x (w x r); both sensors pass a
// 2nd-order Butterworth low-pass, are sampled at the rate, get white noise, and clip at
// ±4000 °/s and ±16 g (flagged). Sensor axes may be rotated against body axes.
// Host only (std::vector): the bare-metal runner has no heap.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <vector>

#include "aloft/sensor/imu_sample.hpp"
#include "aloft/dynamics/inertia_tensor.hpp"
#include "low_pass.hpp"      // tests/diagnose/generator
#include "rotor_flight.hpp"  // tests/diagnose/generator

namespace aloft_test {

using V3 = aloft::Vec3<double>;
using M3 = aloft::Mat3<double>;
using Q = aloft::Quat<double>;

enum class MotionKind { spin_throw, drop, still, waving };
enum class LandingKind { catch_by_hand, impact };

struct TrueFlight {
  double release_s = 0;
  double force_below_1_s = 0;  // the hand's force at the centre of mass last fell below 1 m/s²
  double first_let_go_s = 0;   // with a re-touch: where the force first fell away (else release_s)
  double retouch_start_s = 0;  // with a re-touch: where the finger touched again (else release_s)
  double landing_s = 0;
  double release_rate_rad_s = 0;
  // With a rotor, the total angular momentum R(q) (I ω + h) in world axes at the release
  // and at the landing (constant in flight), and the rotor's profile (recording clock).
  V3 momentum_world_release = V3::Zero();
  V3 momentum_world_landing = V3::Zero();
  aloft::test::RotorProfile rotor_profile{0.0, 0.2, false, 0.0, 0.0, 0.1};
};

struct Recording {
  std::vector<aloft::ImuSample<double>> samples;
  std::vector<TrueFlight> flights;
  std::uint64_t t0_us = 0;  // stamp of t = 0 s
  double rate_hz = 0;
  MotionKind kind = MotionKind::spin_throw;
  V3 imu_position_m = V3::Zero();
  Q sensor_to_body = Q::Identity();
  M3 true_tensor = M3::Identity();
  M3 nominal_tensor = M3::Identity();  // what the pipeline is told (maybe wrong)
  // With a rotor: its moment about its axis (kg m^2), the axis (body axes) and the
  // telemetry; each sample carries the speed as the firmware logged it (rotor_rad_s,
  // flagged imu_rotor_speed).
  double rotor_inertia_kg_m2 = 0;
  V3 rotor_axis = V3::UnitZ();
  aloft::test::RotorTelemetry rotor_telemetry;
};

struct RecordingSpec {
  MotionKind kind = MotionKind::spin_throw;
  double rate_hz = 1000;
  int throws = 3;
  double tensor_error = 0;  // nominal principal moments off by ± this fraction
  bool rotate_sensor = false;
  // A real IMU's errors besides noise: per-axis bias and scale of both sensors, and the
  // accelerometer's axes turned against the gyro's (drawn after everything else, so the
  // recordings without them stay as they were).
  bool sensor_errors = false;
  // Each sampling interval drawn within ± this fraction of the period, as a phone or a
  // logger without a hardware clock samples (the time stamps stay honest: each is the
  // sample's true time, on the simulation's 0.1 ms grid), from draws of their own, so that
  // the throws are the same as without. 0: a regular clock.
  double interval_jitter = 0.0;
  // Slow let-go, hand torque to the end of it, ringing body (see the file comment), from
  // draws of their own so that the rest of the recording is drawn as without.
  bool real_hand = false;
  // A finger touching again for 5-15 ms after the let-go (see the file comment), from
  // draws of its own.
  bool retouch = false;
  // A rotor whose speed is logged (see the file comment), from draws of its own.
  bool rotor = false;
  std::uint32_t seed = 1;
};

class ThrowGenerator {
 public:
  explicit ThrowGenerator(const RecordingSpec& spec) : spec_(spec), rng_(spec.seed) {}

  Recording generate() {
    pick_body();
    fine_dt_ = std::min(1e-4, 0.1 / spec_.rate_hz);
    t_ = 0;
    hold(uniform(0.4, 0.8));
    for (int i = 0; i < spec_.throws; ++i) {
      switch (spec_.kind) {
        case MotionKind::spin_throw: throw_once(uniform(0.0, 1.0) < 0.15 ? 0.0 : uniform(3.0, 40.0)); break;
        case MotionKind::drop: throw_once(-1.0); break;
        case MotionKind::still: hold(2.0); break;
        case MotionKind::waving: wave(uniform(1.0, 2.0)); break;
      }
      hold(uniform(0.6, 1.2));
    }
    return out_;
  }

 private:
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  double hand_uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(hand_rng_);
  }
  double retouch_uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(retouch_rng_);
  }
  V3 retouch_unit() {
    const double x = retouch_uniform(-1, 1), y = retouch_uniform(-1, 1), z = retouch_uniform(-1, 1);
    return V3(x, y, z).normalized();
  }
  double rotor_uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rotor_rng_);
  }
  double normal() { return std::normal_distribution<double>(0.0, 1.0)(rng_); }
  // The draws of one expression are made one statement at a time: the order in which a
  // compiler evaluates function arguments is unspecified (gcc and clang differ), and the
  // recordings must not depend on the compiler. The order is the one gcc chose before.
  V3 normal3() {
    const double z = normal();
    const double y = normal();
    return V3(normal(), y, z);
  }
  V3 unit() { return normal3().normalized(); }
  V3 unit_times(double lo, double hi) {  // a random direction, length uniform in [lo, hi)
    const double length = uniform(lo, hi);
    return unit() * length;
  }
  V3 uniform3(double lo, double hi) {
    const double z = uniform(lo, hi);
    const double y = uniform(lo, hi);
    return V3(uniform(lo, hi), y, z);
  }

  void pick_body() {
    // Shapes: a long rod, a flat disc, a box, a near-sphere, a T-handle-like asymmetric top.
    static const double kShapes[5][3] = {
        {1, 5, 5.2}, {1, 1.05, 2}, {1, 1.6, 2.3}, {1, 1.1, 1.2}, {1, 2.2, 2.9}};
    const int shape = static_cast<int>(uniform(0, 5));
    const double scale = uniform(2e-4, 2e-3);
    const V3 moments = V3(kShapes[shape][0], kShapes[shape][1], kShapes[shape][2]) * scale;
    const Q axes = Q(aloft::quat_exp<double>(unit_times(0, 3.1)));
    const M3 r = axes.toRotationMatrix();
    out_.true_tensor = r * moments.asDiagonal() * r.transpose();
    V3 nominal = moments;
    for (int i = 0; i < 3; ++i) nominal[i] *= 1.0 + (uniform(0, 1) < 0.5 ? -1.0 : 1.0) * spec_.tensor_error;
    std::sort(nominal.data(), nominal.data() + 3);
    if (nominal[2] > nominal[0] + nominal[1]) nominal[2] = nominal[0] + nominal[1];  // stay a body
    out_.nominal_tensor = r * nominal.asDiagonal() * r.transpose();
    out_.imu_position_m = unit_times(0.005, 0.060);
    out_.sensor_to_body = spec_.rotate_sensor ? aloft::quat_exp<double>(unit_times(0, 3.1)) : Q::Identity();
    out_.rate_hz = spec_.rate_hz;
    out_.kind = spec_.kind;
    out_.t0_us = 1000000 + static_cast<std::uint64_t>(uniform(0, 1e6));
    cutoff_hz_ = std::min(0.25 * spec_.rate_hz, 500.0);
    gyro_noise_ = uniform(0.002, 0.02);
    accel_noise_ = uniform(0.02, 0.15);
    tremor_phase_ = uniform3(0, 6.3);
    gyro_filter_ = aloft::generator::LowPass(cutoff_hz_, fine_step());
    accel_filter_ = aloft::generator::LowPass(cutoff_hz_, fine_step());
    if (spec_.sensor_errors) pick_sensor_errors();
    if (spec_.rotor) pick_rotor(moments.minCoeff());
  }

  // Datasheet-sized errors of a MEMS IMU after a factory trim: accelerometer bias
  // ±0.4 m/s² and scale ±2 %, gyro bias ±0.02 rad/s and scale ±1 %, the two sensors' axes
  // up to 1° apart.
  void pick_sensor_errors() {
    accel_bias_ = uniform3(-0.4, 0.4);
    accel_scale_ = V3::Ones() + uniform3(-0.02, 0.02);
    gyro_bias_ = uniform3(-0.02, 0.02);
    gyro_scale_ = V3::Ones() + uniform3(-0.01, 0.01);
    accel_axes_ = aloft::quat_exp<double>(unit_times(0, 0.01745));
  }
  double fine_step() const { return std::min(1e-4, 0.1 / spec_.rate_hz); }

  // The hand holds the body: g up, a little tremor of force and rate.
  void hold(double seconds) {
    const double end = t_ + seconds;
    const double amp = spec_.kind == MotionKind::still ? 0.0 : 1.0;
    while (t_ < end) {
      const V3 s(std::sin(7.0 * t_ + tremor_phase_.x()), std::sin(9.0 * t_ + tremor_phase_.y()),
                 std::sin(5.0 * t_ + tremor_phase_.z()));
      step(V3(0, 0, 9.81) + amp * 0.3 * s, amp * 0.15 * s);
    }
  }

  // Swing with force and torque, release (rate > 0), or open the hand (rate < 0: a drop).
  void throw_once(double release_rate) {
    const bool drop = release_rate < 0;
    const double swing = drop ? uniform(0.05, 0.2) : uniform(0.15, 0.35);
    // Contact ends at a finite rate: the force falls to zero with a slope, not tangentially.
    const double fast_taper = uniform(0.002, 0.010);
    const double taper = spec_.real_hand ? hand_uniform(0.002, 0.030) : fast_taper;
    const bool torque_to_the_end = !drop && uniform(0, 1) < 0.5;
    const V3 w0 = omega_;
    const V3 w_rel = drop ? unit_times(0.0, 0.4) : V3(unit() * release_rate);
    const double peak = drop ? 0.0 : uniform(10, 40);
    const double theta0 = uniform(-1.0, 1.0);
    const V3 across = unit();
    const double start = t_;
    const double release = t_ + swing;
    double force_below_1_s = t_;
    while (t_ < release - 0.5 * fine_dt_) {
      const double u = (t_ - start) / swing;
      const double ramp = u < 0.3 ? (u / 0.3) * (u / 0.3) * (3 - 2 * u / 0.3) : 1.0;
      const double th = theta0 + 1.57 * u;
      const V3 dir = (V3(std::cos(th), 0, std::sin(th)) + 0.3 * across).normalized();
      V3 f = (1 - ramp) * V3(0, 0, 9.81) + ramp * peak * dir;
      if (drop) f = V3(0, 0, 9.81);
      const double left = release - t_;
      if (left < taper) f *= let_go_fraction(left / taper);
      if (f.norm() >= 1.0) force_below_1_s = t_ + fine_dt_;
      // A real hand's torque lasts as long as its force: the rate changes to the end.
      const double sigma = torque_to_the_end || spec_.real_hand ? u * u : u * u * (3 - 2 * u);
      step(f, w0 + (w_rel - w0) * sigma);
    }
    const double first_let_go_s = t_;
    double retouch_start_s = t_;
    if (spec_.retouch) {
      const double th = theta0 + 1.57;
      const V3 push = drop ? V3(0, 0, 1) : (V3(std::cos(th), 0, std::sin(th)) + 0.3 * across).normalized();
      force_below_1_s = retouch(push, retouch_start_s);
    }
    out_.flights.push_back(
        {t_, std::min(force_below_1_s, t_), first_let_go_s, retouch_start_s, 0.0, w_rel.norm()});
    if (spec_.real_hand) start_ringing();
    const double airborne = drop ? uniform(0.15, 0.5) : uniform(0.25, 0.8);
    if (spec_.rotor && !drop) {
      rotor_profile_ = draw_rotor_profile(t_);
      out_.flights.back().rotor_profile = rotor_profile_;
      fly_with_rotor(airborne + rotor_uniform(0.15, 0.35));
    } else {
      fly(airborne);
    }
    out_.flights.back().landing_s = t_;
    const LandingKind landing = uniform(0, 1) < 0.5 ? LandingKind::catch_by_hand : LandingKind::impact;
    if (spec_.real_hand && landing == LandingKind::catch_by_hand) start_ringing();
    land(landing);
  }

  // The finger that touches again (see the file comment): the hand's force gone for 2-4 ms,
  // then a push near the swing's last direction with a torque, integrated with Euler's
  // equations (RK4 on the fine grid); returns the last instant the force was >= 1 m/s²,
  // and where the finger touched in `touched_s`.
  double retouch(const V3& push_world, double& touched_s) {
    const double gap = retouch_uniform(0.002, 0.004);
    const double touch = retouch_uniform(0.005, 0.015);
    const double peak = retouch_uniform(3.0, 4.0);
    const double rise = retouch_uniform(0.001, 0.003);
    const double fall = retouch_uniform(0.001, 0.003);
    const V3 dir = (push_world + 0.5 * retouch_unit()).normalized();
    // Mass from the mean moment and a radius of gyration; the contact 1-2 radii out.
    const double gyration_m = retouch_uniform(0.03, 0.06);
    const double mass_kg = out_.true_tensor.trace() / 3.0 / (gyration_m * gyration_m);
    const V3 contact = retouch_unit() * (gyration_m * retouch_uniform(1.0, 2.0));
    const M3& inertia = out_.true_tensor;
    const M3 inverse = inertia.inverse();
    const double start = t_;
    touched_s = start + gap;
    double last_above_1 = t_;
    while (t_ < start + gap + touch - 0.5 * fine_dt_) {
      const double s = t_ - start - gap;  // into the touch
      double level = 0.0;
      if (s >= 0.0) {
        const double up = s < rise ? 0.5 - 0.5 * std::cos(3.14159265 * s / rise) : 1.0;
        const double left = touch - s;
        const double down = left < fall ? 0.5 - 0.5 * std::cos(3.14159265 * left / fall) : 1.0;
        level = peak * std::min(up, down);
      }
      const V3 f_world = level * dir;
      const V3 torque_per_mass = contact.cross(orientation_.conjugate() * f_world);
      auto rate = [&](const V3& w) -> V3 {
        return inverse * (mass_kg * torque_per_mass - w.cross(inertia * w));
      };
      const double h = fine_dt_;
      const V3 k1 = rate(omega_);
      const V3 k2 = rate(omega_ + 0.5 * h * k1);
      const V3 k3 = rate(omega_ + 0.5 * h * k2);
      const V3 k4 = rate(omega_ + h * k3);
      if (level >= 1.0) last_above_1 = t_ + fine_dt_;
      step(f_world, omega_ + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4));
    }
    return last_above_1;
  }

  // The fraction of the swing's force left with a fraction x of the let-go to go: the fast
  // let-go ends as a quarter sine (a finite slope at zero); a real hand's falls as
  // x (0.25 + 0.75 x), slowly at first and with a slow tail (a quarter of the mean slope).
  double let_go_fraction(double x) const {
    return spec_.real_hand ? x * (0.25 + 0.75 * x) : std::sin(1.5707963 * x);
  }

  // One or two structural modes of the body, struck by the hand letting go or catching:
  // along a fixed body direction each, 100-800 Hz, decaying over 5-30 ms, 2-8 m/s² at
  // first (before the sensor's low-pass).
  void start_ringing() {
    const int modes = hand_uniform(0, 1) < 0.5 ? 1 : 2;
    for (int m = 0; m < 2; ++m) {
      RingingMode& mode = ringing_[m];
      mode.amplitude_m_s2 = m < modes ? hand_uniform(2.0, 8.0) : 0.0;
      mode.frequency_hz = hand_uniform(100.0, 800.0);
      mode.decay_s = hand_uniform(0.005, 0.030);
      const double x = hand_uniform(-1, 1), y = hand_uniform(-1, 1), z = hand_uniform(-1, 1);
      mode.direction = V3(x, y, z).normalized();
      mode.start_s = t_;
    }
  }
  V3 ringing(double t) const {
    V3 sum = V3::Zero();
    for (const RingingMode& mode : ringing_) {
      const double s = t - mode.start_s;
      if (mode.amplitude_m_s2 <= 0 || s < 0 || s > 8 * mode.decay_s) continue;
      sum += mode.direction * (mode.amplitude_m_s2 * std::exp(-s / mode.decay_s) *
                               std::sin(6.283185307 * mode.frequency_hz * s));
    }
    return sum;
  }

  // The rotor's body-fixed constants, once per recording.
  void pick_rotor(double smallest_moment) {
    out_.rotor_inertia_kg_m2 = smallest_moment * rotor_uniform(0.003, 0.012);
    const double x = rotor_uniform(-1, 1), y = rotor_uniform(-1, 1), z = rotor_uniform(-1, 1);
    out_.rotor_axis = V3(x, y, z).normalized();
    aloft::test::RotorTelemetry& telemetry = out_.rotor_telemetry;
    telemetry.period_s = rotor_uniform(0.000125, 0.002);
    telemetry.delay_s = rotor_uniform(0.001, 0.004);
    telemetry.first_frame_s = rotor_uniform(0.0, telemetry.period_s);
    telemetry.pole_pairs = rotor_uniform(0, 1) < 0.5 ? 6 : 7;
    // ALOFT_ROTOR_TELEMETRY_EXACT: the speed read without delay or hold (a frame every 10 µs),
    // after the draws (the throws stay the same), to measure what the telemetry costs.
    if (std::getenv("ALOFT_ROTOR_TELEMETRY_EXACT") != nullptr) {
      telemetry.delay_s = 0.0;
      telemetry.period_s = 1e-5;
      telemetry.first_frame_s = 0.0;
    }
  }

  aloft::test::RotorProfile draw_rotor_profile(double release_s) {
    aloft::test::RotorProfile p;
    p.start_s = release_s + rotor_uniform(0.0, 0.06);
    p.spin_up_s = rotor_uniform(0.15, 0.25);
    p.first_order = rotor_uniform(0, 1) < 0.5;
    p.full_rad_s = (rotor_uniform(0, 1) < 0.5 ? -1.0 : 1.0) * rotor_uniform(300.0, 1500.0);
    p.hold_s = rotor_uniform(0.05, 0.2);
    p.brake_s = rotor_uniform(0.05, 0.15);
    return p;
  }

  void fly(double seconds) {
    const double end = t_ + seconds;
    const V3 drag = unit_times(0, 0.3);
    const M3 inverse = out_.true_tensor.inverse();
    const M3& i = out_.true_tensor;
    auto rate = [&](const V3& w) -> V3 { return inverse * (-w.cross(i * w)); };
    while (t_ < end) {
      const double h = fine_dt_;
      const V3 k1 = rate(omega_);
      const V3 k2 = rate(omega_ + 0.5 * h * k1);
      const V3 k3 = rate(omega_ + 0.5 * h * k2);
      const V3 k4 = rate(omega_ + h * k3);
      step(orientation_ * drag, omega_ + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4));
    }
  }

  // The gyrostat (rotor_flight.hpp): its own RK4 on orientation and rate, split at the
  // profile's corners; the world momentum at both ends is kept for the tests.
  void fly_with_rotor(double seconds) {
    const double end = t_ + seconds;
    const V3 drag = unit_times(0, 0.3);
    const aloft::test::RotorFlight flight(out_.true_tensor, out_.rotor_inertia_kg_m2, out_.rotor_axis,
                                          rotor_profile_);
    aloft::test::GyrostatState state;
    state.q = orientation_;
    state.w = omega_;
    out_.flights.back().momentum_world_release = flight.world_momentum(t_, state);
    while (t_ < end) {
      flight.advance(t_, fine_dt_, state);
      step(orientation_ * drag, state.w);
    }
    out_.flights.back().momentum_world_landing = flight.world_momentum(t_, state);
  }

  void land(LandingKind kind) {
    const bool impact = kind == LandingKind::impact;
    const double rise = impact ? uniform(0.001, 0.002) : uniform(0.005, 0.015);
    const double peak = impact ? uniform(200, 1500) : uniform(20, 60);
    const double pulse = impact ? uniform(0.002, 0.004) : uniform(0.05, 0.1);
    const V3 w_land = omega_;
    const V3 w_after = impact ? unit_times(0, 5) : V3(V3::Zero());
    const double fade = impact ? rise : uniform(0.03, 0.08);
    const V3 dir = unit();
    const double start = t_;
    while (t_ < start + rise + pulse) {
      const double s = t_ - start;
      const double up = s < rise ? 0.5 - 0.5 * std::cos(3.14159265 * s / rise) : 1.0;
      const double k = std::min(1.0, s / fade);
      const V3 w = w_land + (w_after - w_land) * (k * k * (3 - 2 * k));
      step(up * (peak * dir + V3(0, 0, 9.81)), w);
    }
    // Settle into the hand (or onto the floor): rate to zero over 50 ms.
    const V3 w_settle = omega_;
    const double settle = t_;
    while (t_ < settle + 0.05) {
      const double k = (t_ - settle) / 0.05;
      step(V3(0, 0, 9.81), w_settle * (1 - k * k * (3 - 2 * k)));
    }
  }

  // Hand waving the body around without letting go: force and rate swing back and forth,
  // the hand never lets the specific force fall far below g.
  void wave(double seconds) {
    const double end = t_ + seconds;
    const V3 spin = unit_times(3, 15);
    const double f_hz = uniform(1.5, 4);
    const double dir_z = uniform(-0.3, 0.3);
    const V3 dir = V3(1, uniform(-1, 1), dir_z).normalized();
    const double amp = uniform(5, 20);
    const double start = t_;
    while (t_ < end) {
      const double s = std::sin(6.2831853 * f_hz * (t_ - start));
      const double c = std::cos(6.2831853 * f_hz * (t_ - start));
      step(V3(0, 0, 9.81) + amp * s * dir, spin * c);
    }
  }

  // Advances the fine grid by one step to rate w_next under world force f (specific force
  // at the centre of mass), and samples the sensors when a sample instant is passed.
  void step(const V3& f_world, const V3& w_next) {
    const V3 w_dot = (w_next - omega_) / fine_dt_;
    const V3 w_mid = 0.5 * (w_next + omega_);
    const V3 f_body = orientation_.conjugate() * f_world;
    const V3 r = out_.imu_position_m;
    V3 accel_body = f_body + w_dot.cross(r) + w_mid.cross(w_mid.cross(r));
    if (spec_.real_hand) accel_body += ringing(t_);
    orientation_ = (orientation_ * aloft::quat_exp<double>(w_mid * fine_dt_)).normalized();
    omega_ = w_next;
    t_ += fine_dt_;
    const Q body_to_sensor = out_.sensor_to_body.conjugate();
    if (!filters_settled_) {  // held still since long before the recording
      gyro_filter_.settle(body_to_sensor * w_mid);
      accel_filter_.settle(body_to_sensor * accel_body);
      filters_settled_ = true;
    }
    const V3 gyro_f = gyro_filter_(body_to_sensor * w_mid);
    const V3 accel_f = accel_filter_(body_to_sensor * accel_body);
    const double period = 1.0 / spec_.rate_hz;
    if (t_ + 1e-12 < next_sample_s_) return;
    const double jitter = spec_.interval_jitter;
    next_sample_s_ += period * (1.0 + std::uniform_real_distribution<double>(-jitter, jitter)(jitter_rng_));
    aloft::ImuSample<double> s;
    s.t_us = out_.t0_us + static_cast<std::uint64_t>(std::llround(t_ * 1e6));
    s.gyro_rad_s = gyro_scale_.cwiseProduct(gyro_f) + gyro_bias_ + gyro_noise_ * normal3();
    s.accel_m_s2 = accel_scale_.cwiseProduct(accel_axes_ * accel_f) + accel_bias_ + accel_noise_ * normal3();
    clip(s.gyro_rad_s, 69.8, aloft::imu_gyro_clipped, s.flags);
    clip(s.accel_m_s2, 156.9, aloft::imu_accel_clipped, s.flags);
    if (spec_.rotor) {
      s.rotor_rad_s = out_.rotor_telemetry.logged(t_, rotor_profile_);
      s.flags = static_cast<std::uint8_t>(s.flags | aloft::imu_rotor_speed);
    }
    out_.samples.push_back(s);
  }

  static void clip(V3& v, double limit, std::uint8_t flag, std::uint8_t& flags) {
    for (int i = 0; i < 3; ++i) {
      if (std::abs(v[i]) >= limit) {
        v[i] = v[i] > 0 ? limit : -limit;
        flags = static_cast<std::uint8_t>(flags | flag);
      }
    }
  }

  RecordingSpec spec_;
  std::mt19937 rng_;
  // The sampling intervals' own draws: the same throws with and without jitter.
  std::mt19937 jitter_rng_{spec_.seed ^ 0x5EEDu};
  // The real hand's draws (let-go span, ringing): the same throws with and without it.
  std::mt19937 hand_rng_{spec_.seed ^ 0x4A4Du};
  // The re-touch's draws: the same throws with and without it.
  std::mt19937 retouch_rng_{spec_.seed ^ 0x70C4u};
  // The rotor's draws: the same throws with and without it (but for the longer flights).
  std::mt19937 rotor_rng_{spec_.seed ^ 0x2070u};
  aloft::test::RotorProfile rotor_profile_{0.0, 0.2, false, 0.0, 0.0, 0.1};
  struct RingingMode {
    double amplitude_m_s2 = 0;
    double frequency_hz = 0;
    double decay_s = 1;
    double start_s = 0;
    V3 direction = V3::UnitX();
  };
  RingingMode ringing_[2];
  Recording out_;
  double t_ = 0;
  double fine_dt_ = 1e-4;
  double next_sample_s_ = 0;
  double cutoff_hz_ = 100;
  double gyro_noise_ = 0.01;
  double accel_noise_ = 0.05;
  V3 tremor_phase_ = V3::Zero();
  V3 accel_bias_ = V3::Zero();  // pick_sensor_errors(); none by default
  V3 accel_scale_ = V3::Ones();
  V3 gyro_bias_ = V3::Zero();
  V3 gyro_scale_ = V3::Ones();
  Q accel_axes_ = Q::Identity();
  V3 omega_ = V3::Zero();
  Q orientation_ = Q::Identity();
  aloft::generator::LowPass gyro_filter_{0, 1};  // set in pick_body()
  aloft::generator::LowPass accel_filter_{0, 1};
  bool filters_settled_ = false;
};

}  // namespace aloft_test
