// The release window (aloft/onboard/release_window.hpp): a proposed release, judged over blocks
// of 5 ms once 25 ms of samples have followed it (a later look: 50 ms).
#include "aloft/onboard/release_window.hpp"

#include <cmath>

#include "test_api.hpp"

namespace {

// The window holds its settings by reference (a pipeline's parts share one copy).
const aloft::ReleaseWindowSettings<float> default_settings;

using V3 = aloft::Vec3<float>;
using Window = aloft::ReleaseWindow<float>;

constexpr std::uint64_t t0_us = 5000000;
constexpr std::uint32_t period_us = 250;  // 4 kHz: 20 samples a block
const V3 r_true(0.035f, -0.02f, 0.0f);

// Sample i of a body spinning at 25 rad/s, accelerometer at r_true, plus `extra` (m/s²).
aloft::BodyKinematics<float> kinematics(const V3& extra) {
  aloft::BodyKinematics<float> k;
  k.w = V3(1.0f, -0.5f, 25.0f);
  k.a = aloft::lever_arm_matrix(k.w, k.w_dot) * r_true + extra;
  return k;
}

// r given: the window fits r within 10 mm of r_true.
aloft::LeverArmBall<float> given_r() {
  aloft::LeverArmBall<float> ball;
  ball.centre = r_true;
  ball.radius_m = 0.01f;
  ball.otherwise = r_true;
  return ball;
}

std::uint64_t stamp(std::uint32_t i) { return t0_us + static_cast<std::uint64_t>(i) * period_us; }

// Feeds samples [from, to) with the hand's push (m/s²) fading linearly to zero at sample
// `hand_ends`, and a ringing mode of `ring_m_s2` at 300 Hz, decaying over 10 ms, from `hand_ends` on; returns
// the first decided verdict for the release proposed at sample `proposed`.
aloft::WindowedRelease<float> feed(Window& w, std::uint32_t to, std::uint32_t hand_ends, float push_m_s2,
                                   float ring_m_s2, std::uint32_t proposed) {
  const aloft::LeverArmBall<float> ball = given_r();
  aloft::WindowedRelease<float> verdict;
  for (std::uint32_t i = 0; i < to && !verdict.decided; ++i) {
    V3 extra = V3::Zero();
    if (i < hand_ends) extra = V3(0, 1, 0) * (push_m_s2 * static_cast<float>(hand_ends - i) / 80.0f);
    const float t_s = static_cast<float>(i - (i < hand_ends ? i : hand_ends)) * 250e-6f;
    if (i >= hand_ends)
      extra = V3(1, 0, 0) * (ring_m_s2 * std::exp(-t_s / 0.01f) * std::sin(6.2831853f * 300.0f * t_s));
    w.add(i, stamp(i), kinematics(extra), true);
    if (i >= proposed) verdict = w.date(proposed, stamp(proposed), ball);
  }
  return verdict;
}

}  // namespace

ALOFT_TEST_CASE("release window: free flight from the proposal keeps the proposed release",
                "[release_window]") {
  Window w{default_settings};
  const aloft::WindowedRelease<float> v = feed(w, 600, 200, 15.0f, 0.0f, 205);
  ALOFT_CHECK(v.decided);
  ALOFT_CHECK(v.free);
  ALOFT_CHECK(v.index == 205u);
  ALOFT_CHECK(v.release_us == stamp(205));
}

ALOFT_TEST_CASE("release window: a hand that still pushes after the proposal moves the release later",
                "[release_window]") {
  // The hand's push fades over 80 samples (20 ms) to sample 300; proposed at 268 (8 ms
  // early, 6 m/s² left): the release moves to the block that starts where the hand let go.
  Window w{default_settings};
  const aloft::WindowedRelease<float> v = feed(w, 800, 300, 15.0f, 0.0f, 268);
  ALOFT_CHECK(v.decided);
  ALOFT_CHECK(v.free);
  ALOFT_CHECK(v.index == 300u);
  ALOFT_CHECK(v.release_us == stamp(300));
}

ALOFT_TEST_CASE("release window: proposed while the hand pushes for most of the window, it is withdrawn",
                "[release_window]") {
  // Proposed at 240 (15 ms early): when the window is full only 10 ms of free flight
  // follow the hand, under min_free_us.
  Window w{default_settings};
  const aloft::WindowedRelease<float> v = feed(w, 800, 300, 15.0f, 0.0f, 240);
  ALOFT_CHECK(v.decided);
  ALOFT_CHECK(!v.free);
}

ALOFT_TEST_CASE("release window: a ringing body is free flight (its mode averages out of a block)",
                "[release_window]") {
  // 300 Hz at 5 m/s² from the release on, decaying over 10 ms: single samples over the
  // sample-by-sample limit
  // (2 + 0.1 |K r| = 4.2 m/s² here), their block means at most a fifth of it.
  Window w{default_settings};
  const aloft::WindowedRelease<float> v = feed(w, 800, 200, 15.0f, 5.0f, 200);
  ALOFT_CHECK(v.decided);
  ALOFT_CHECK(v.free);
  ALOFT_CHECK(v.release_us == stamp(200));
}

ALOFT_TEST_CASE("release window: a push that never ends withdraws the proposal", "[release_window]") {
  Window w{default_settings};
  // The hand pushes to sample 10000 (still 15 m/s² · 90 % over the window): no free run.
  const aloft::WindowedRelease<float> v = feed(w, 400, 10000, 15.0f, 0.0f, 100);
  ALOFT_CHECK(v.decided);
  ALOFT_CHECK(!v.free);
}

namespace {

// A finger that touches again after the release at sample 200: 3.5 m/s² along `along`
// from sample `from` to `to` (by default along y, 250 to 290, 10 ms); free flight before
// and after.
struct Finger {
  std::uint32_t from = 250, to = 290;
  V3 along = V3(0, 1, 0);
  V3 push(std::uint32_t i) const { return i >= from && i < to ? V3(along * 3.5f) : V3::Zero(); }
};

// Feeds samples to `to` (free flight from sample 200, with the finger's push on it when
// `finger`) and dates the release at `release` (a later look when `later_look`) once the
// window has seen enough.
aloft::WindowedRelease<float> date_release(Window& w, std::uint32_t to, std::uint32_t release,
                                           bool later_look, bool finger, const Finger& f = Finger{}) {
  const aloft::LeverArmBall<float> ball = given_r();
  aloft::WindowedRelease<float> verdict;
  for (std::uint32_t i = 0; i < to && !verdict.decided; ++i) {
    const float push = i < 200 ? 15.0f * static_cast<float>(200 - i) / 80.0f : 0.0f;  // the hand's fade
    const V3 hand = V3(0, 1, 0) * push;
    w.add(i, stamp(i), kinematics(finger ? hand + f.push(i) : hand), true);
    if (i >= release) verdict = w.date(release, stamp(release), ball, later_look);
  }
  return verdict;
}

}  // namespace

ALOFT_TEST_CASE(
    "release window: a push inside the fit blocks leaves the fit unsettled, and a later look dates past it",
    "[release_window]") {
  // Proposed at 200, the first look (25 ms on: fit blocks 240-300) takes the finger into
  // the flight's level, and dates the release at 240, into the push.
  Window first{default_settings};
  const aloft::WindowedRelease<float> v = date_release(first, 800, 200, false, true);
  ALOFT_CHECK(v.decided);
  ALOFT_CHECK(v.free);
  ALOFT_CHECK(!v.settled);
  ALOFT_CHECK(v.index < 290u);
  // A later look (50 ms past that release) fits the flight past the push: the release comes
  // after the finger lets go (sample 290), within a block, and this fit is settled.
  Window later{default_settings};
  const aloft::WindowedRelease<float> l = date_release(later, 800, v.index, true, true);
  ALOFT_CHECK(l.decided);
  ALOFT_CHECK(l.free);
  ALOFT_CHECK(l.settled);
  ALOFT_CHECK(l.index >= 290u);
  ALOFT_CHECK(l.index <= 310u);
  ALOFT_CHECK(l.release_us > v.release_us);
}

ALOFT_TEST_CASE(
    "release window: a push through all the fit blocks is no flight's level: unsettled, a later look dates "
    "past it",
    "[release_window]") {
  // The finger pushes from sample 230 to 330 (25 ms), along the spin axis (where no lever
  // arm within the given r's 10 mm takes it up, as none does a push fixed in the world on a
  // turning body): the first look's fit blocks (240-300) lie at its level, 3.5 m/s² from
  // zero where a free block's limit is 0.8 + 0.02 |K r| (|K r| about 25 m/s²: 1.3 m/s²),
  // and the blocks from 240 on look free against it.
  const Finger long_finger{230, 330, V3(1.0f, -0.5f, 25.0f).normalized()};
  Window first{default_settings};
  const aloft::WindowedRelease<float> v = date_release(first, 800, 200, false, true, long_finger);
  ALOFT_CHECK(v.decided);
  ALOFT_CHECK(v.free);
  ALOFT_CHECK(v.index < 330u);
  ALOFT_CHECK(!v.settled);
  // The later look fits the flight past the push, and dates the release after it.
  Window later{default_settings};
  const aloft::WindowedRelease<float> l = date_release(later, 900, v.index, true, true, long_finger);
  ALOFT_CHECK(l.decided);
  ALOFT_CHECK(l.settled);
  ALOFT_CHECK(l.index >= 330u);
  ALOFT_CHECK(l.index <= 350u);
}

ALOFT_TEST_CASE(
    "release window: a push through the block that holds the proposal dates the release past it; a let-go "
    "that ended before the proposal keeps it",
    "[release_window]") {
  // Proposed at 230, halfway into the block 220-240; a finger pushes from 205 to 236. That
  // block's mean (2.8 m/s²) lies above what the block before (2.6 m/s²) could leave before
  // the proposal plus a free stretch after it (0.5 x 2.6 + 0.5 x 0.8): the push went on
  // past the proposal, and the release moves past its end (236), into the next block.
  Window pushed{default_settings};
  const aloft::WindowedRelease<float> v = date_release(pushed, 800, 230, false, true, Finger{205, 236});
  ALOFT_CHECK(v.decided);
  ALOFT_CHECK(v.free);
  ALOFT_CHECK(v.index >= 236u);
  ALOFT_CHECK(v.index <= 245u);
  ALOFT_CHECK(v.release_us == stamp(v.index));
  // The hand's push (60 m/s² scale) fades to zero at sample 210, the release proposed at
  // 212: the block 200-220 is not free (mean 2.1 m/s²), but a falling push before the
  // proposal accounts for it (at most 0.6 of the block before's 15 m/s²).
  Window let_go{default_settings};
  const aloft::WindowedRelease<float> kept = feed(let_go, 800, 210, 60.0f, 0.0f, 212);
  ALOFT_CHECK(kept.free);
  ALOFT_CHECK(kept.index == 212u);
}

ALOFT_TEST_CASE("release window: free flight leaves the fit settled", "[release_window]") {
  Window w{default_settings};
  const aloft::WindowedRelease<float> v = feed(w, 600, 200, 15.0f, 0.0f, 205);
  ALOFT_CHECK(v.decided);
  ALOFT_CHECK(v.settled);
}

ALOFT_TEST_CASE("release window: a later look whose blocks do not reach back to the release keeps it",
                "[release_window]") {
  // window_us above the default the ring is sized for: the later look, 80 ms on, holds
  // blocks from about 25 ms after the release only, all free; where the free flight starts
  // is not seen, so the release stays (not moved to the oldest block held).
  aloft::ReleaseWindowSettings<float> settings;
  settings.window_us = 40000;
  Window w{settings};
  const aloft::WindowedRelease<float> v = date_release(w, 1000, 205, true, false);
  ALOFT_CHECK(v.decided);
  ALOFT_CHECK(v.free);
  ALOFT_CHECK(v.index == 205u);
  ALOFT_CHECK(v.release_us == stamp(205));
}

namespace {

// The body of kinematics(): a spin of 25 rad/s about z, nearly its principal axis.
aloft::Mat3<float> spin_tensor() { return aloft::Vec3<float>(0.010f, 0.012f, 0.020f).asDiagonal(); }

// Feeds samples: free flight from sample 200 after the hand's fade, except that from
// sample `from` to `to` a finger's torque turns the body at 60 rad/s² about y with no force
// at the centre of mass (the accelerometer reads K r: the force of a drop's finger that
// cancels against its own lever arm). Dates the release proposed at 205 with the torque
// tested against `inertia` (none: not tested).
aloft::WindowedRelease<float> date_past_torque(Window& w, const aloft::Mat3<float>* inertia,
                                               std::uint32_t from = 220, std::uint32_t to = 260) {
  const aloft::LeverArmBall<float> ball = given_r();
  aloft::WindowedRelease<float> verdict;
  for (std::uint32_t i = 0; i < 800 && !verdict.decided; ++i) {
    aloft::BodyKinematics<float> k = kinematics(V3::Zero());
    if (i < 200) k.a += V3(0, 1, 0) * (15.0f * static_cast<float>(200 - i) / 80.0f);
    if (i >= from && i < to) {
      k.w_dot = V3(0, 60.0f, 0);
      k.a = aloft::lever_arm_matrix(k.w, k.w_dot) * r_true;
    }
    w.add(i, stamp(i), k, true);
    if (i >= 205) verdict = w.date(205, stamp(205), ball, false, inertia);
  }
  return verdict;
}

template <typename S>
void check_twice_torque_residual() {
  // Three samples' K summed: twice the sum of I w_dot + w x (I w), whatever the tensor.
  aloft::Mat3<S> inertia;
  inertia << S(0.012), S(0.001), S(-0.002), S(0.001), S(0.015), S(0.0007), S(-0.002), S(0.0007), S(0.021);
  const aloft::Vec3<S> w[3] = {{S(3), S(-20), S(7)}, {S(-1), S(4), S(25)}, {S(11), S(0.5), S(-2)}};
  const aloft::Vec3<S> w_dot[3] = {{S(40), S(-3), S(9)}, {S(0), S(120), S(-30)}, {S(-7), S(2), S(1)}};
  aloft::Mat3<S> k_sum = aloft::Mat3<S>::Zero();
  aloft::Vec3<S> expected = aloft::Vec3<S>::Zero();
  for (int n = 0; n < 3; ++n) {
    k_sum += aloft::lever_arm_matrix(w[n], w_dot[n]);
    expected += S(2) * (inertia * w_dot[n] + w[n].cross(inertia * w[n]));
  }
  const aloft::Vec3<S> got = aloft::twice_torque_residual(inertia, k_sum);
  ALOFT_CHECK((got - expected).norm() <= S(1e-5) * expected.norm());
}

}  // namespace

ALOFT_TEST_CASE("twice_torque_residual: the summed torque-free residual from the lever-arm matrices' sum",
                "[release_window]") {
  check_twice_torque_residual<float>();
  check_twice_torque_residual<double>();
}

ALOFT_TEST_CASE("release window: a torque the accelerometer does not show moves the release past it",
                "[release_window]") {
  // Without the tensor the blocks look free: the proposal stays.
  Window force_only{default_settings};
  const aloft::WindowedRelease<float> f = date_past_torque(force_only, nullptr);
  ALOFT_CHECK(f.decided);
  ALOFT_CHECK(f.free);
  ALOFT_CHECK(f.index == 205u);
  // With it, the finger's blocks are not free: the release comes after the finger (260),
  // within the next block.
  Window with_torque{default_settings};
  const aloft::Mat3<float> inertia = spin_tensor();
  const aloft::WindowedRelease<float> t = date_past_torque(with_torque, &inertia);
  ALOFT_CHECK(t.decided);
  ALOFT_CHECK(t.free);
  ALOFT_CHECK(t.index >= 260u);
  ALOFT_CHECK(t.index <= 280u);
}

ALOFT_TEST_CASE("release window: a torque that would leave too short a run keeps the force's, unsettled",
                "[release_window]") {
  // The finger turns the body from sample 250 to 290: the window, decided about sample 305,
  // would hold under 15 ms of free flight after it. The torque does not withdraw a flight the
  // force leaves free: the force's run stands, and the fit is not settled (the later look
  // dates it).
  Window w{default_settings};
  const aloft::Mat3<float> inertia = spin_tensor();
  const aloft::WindowedRelease<float> v = date_past_torque(w, &inertia, 250, 290);
  ALOFT_CHECK(v.decided);
  ALOFT_CHECK(v.free);
  ALOFT_CHECK(!v.settled);
  ALOFT_CHECK(v.index == 205u);
}
