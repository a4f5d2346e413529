// The release detector's torque test with a rotor (aloft/onboard/torque_test.hpp) on exact
// samples: a gyro rate whose central difference is exactly the gyrostat's ω̇ from Euler's
// equations (aloft/dynamics/euler_equations.hpp), and a logged speed whose difference is
// exactly ṡ. The rotor's torque is then no torque; a torque across its axis is; one along
// it (what late telemetry leaves) is left out; and without a rotor, or without the speed,
// the test is the body's own to the bit.
#include "aloft/onboard/torque_test.hpp"
#include "test_api.hpp"

#include <cstring>

namespace {

using aloft::Vec3;

template <typename S>
bool same_bits(S a, S b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

template <typename S>
aloft::InertiaTensor<S> box() {
  aloft::InertiaTensor<S> inertia;
  ALOFT_REQUIRE(aloft::InertiaTensor<S>::make_box(S(0.5), S(0.05), S(0.08), S(0.12), inertia) ==
                aloft::Status::ok);
  return inertia;
}

// Samples 0, 1, 2 at 1 kHz: sample 1 has rate w and speed s, the others w -/+ w_dot dt and
// s -/+ s_dot dt, so that a central difference over +-1 sample gives w_dot and s_dot.
template <typename S>
struct ExactSamples {
  aloft::SampleHistory<S, 32> history;
  aloft::RotorSpeedHistory<S, 32, true> speeds;

  ExactSamples(const Vec3<S>& w, const Vec3<S>& w_dot, S s, S s_dot, std::uint8_t flags) {
    const S dt = S(1e-3);
    for (int i = 0; i < 3; ++i) {
      const S step = static_cast<S>(i - 1) * dt;
      history.push(1000000u + static_cast<std::uint64_t>(i) * 1000u, w + step * w_dot, Vec3<S>::Zero(),
                   flags);
      speeds.set(static_cast<std::uint32_t>(i), s + step * s_dot, true);
    }
  }
  aloft::BodyKinematics<S> kinematics() const {
    aloft::BodyKinematics<S> k;
    ALOFT_REQUIRE(history.kinematics(1, 1, k));
    return k;
  }
};

template <typename S>
void rotor_torque_is_known() {
  const aloft::InertiaTensor<S> inertia = box<S>();
  aloft::FreeFlightSettings<S> free_flight;
  aloft::Rotor<S> rotor;
  rotor.axis = Vec3<S>(S(1), S(2), S(2)) / S(3);
  rotor.inertia_kg_m2 = S(2e-5);
  const Vec3<S> w(S(1.5), S(-0.5), S(1));
  const S s = S(600), s_dot = S(4000);  // a wheel spinning up: its torque leads the body's
  const Vec3<S> alpha = aloft::angular_acceleration(inertia, w, rotor.momentum(s), rotor.momentum(s_dot));
  const Vec3<S> across = rotor.axis.cross(Vec3<S>::UnitX()).normalized();
  const S hand = S(5) * rotor.inertia_kg_m2 * s_dot;  // a torque five times the rotor's
  const std::uint8_t read = aloft::imu_rotor_speed;
  const ExactSamples<S> free(w, alpha, s, s_dot, read);
  const ExactSamples<S> pushed(w, alpha + inertia.inverse() * (hand * across), s, s_dot, read);
  const ExactSamples<S> late(w, alpha + inertia.inverse() * (hand * rotor.axis), s, s_dot, read);
  const ExactSamples<S> unread(w, alpha, s, s_dot, 0);

  const aloft::GyrostatTorqueTest<S, 32> with_rotor(free_flight, inertia, rotor, free.speeds);
  const aloft::BodyTorqueTest<S> body(free_flight, inertia.tensor());
  ALOFT_CHECK(with_rotor.relative(free.history, 1, 1, free.kinematics()) < S(1e-4));
  ALOFT_CHECK(body.relative(free.history, 1, 1, free.kinematics()) > S(0.5));  // without it: a torque
  const aloft::GyrostatTorqueTest<S, 32> pushed_test(free_flight, inertia, rotor, pushed.speeds);
  ALOFT_CHECK(pushed_test.relative(pushed.history, 1, 1, pushed.kinematics()) > S(0.5));
  const aloft::GyrostatTorqueTest<S, 32> late_test(free_flight, inertia, rotor, late.speeds);
  ALOFT_CHECK(late_test.relative(late.history, 1, 1, late.kinematics()) < S(1e-4));

  // No speed on the samples, or no rotor in the settings: the body's test, to the bit.
  const aloft::GyrostatTorqueTest<S, 32> unread_test(free_flight, inertia, rotor, unread.speeds);
  ALOFT_CHECK(same_bits(unread_test.relative(unread.history, 1, 1, unread.kinematics()),
                        body.relative(unread.history, 1, 1, unread.kinematics())));
  const aloft::Rotor<S> none;
  const aloft::GyrostatTorqueTest<S, 32> no_rotor(free_flight, inertia, none, free.speeds);
  ALOFT_CHECK(same_bits(no_rotor.relative(free.history, 1, 1, free.kinematics()),
                        body.relative(free.history, 1, 1, free.kinematics())));
}

}  // namespace

ALOFT_TEST_CASE("torque test: a logged rotor's torque is known, a hand's across its axis is not",
                "[release][rotor]") {
  rotor_torque_is_known<float>();
  rotor_torque_is_known<double>();
}
