// What free flight looks like to a body-mounted IMU, per sample, in body axes:
//  - accelerometer at r (m, from the centre of mass): in free fall gravity is not sensed,
//    so the specific force is only the lever arm's, a = w_dot x r + w x (w x r) = K(w, w_dot) r
//    with K = [w_dot]x + [w]x^2. A hand's force (or the ground's) adds F/m to it.
//  - gyro, with the nominal tensor I: the torque I w_dot + w x (I w) is zero in flight.
//    A tensor off by a fraction e leaves at most about e (|I w_dot| + |w| |I w|) of it, so
//    the torque is judged relative to that scale: a 20 % wrong tensor cannot reach the
//    limit, a hand that spins the body up (torque ~ I w_dot) does.
// Both tests take w_dot from gyro differences (aloft/onboard/sample_history.hpp), so their
// limits carry a floor for its noise.
#pragma once

#include "aloft/cold_path.hpp"
#include "aloft/dynamics/euler_equations.hpp"
#include "aloft/dynamics/inertia_tensor.hpp"
#include "aloft/dynamics/rotation.hpp"
#include "aloft/settings.hpp"

namespace aloft {

template <typename Scalar>
struct FreeFlightSettings {
  // Specific force left after the lever arm's is removed, counted as free flight:
  // floor + relative * |K r|.
  Scalar accel_floor_m_s2 = Scalar(2.0);
  Scalar accel_relative = Scalar(0.1);
  Scalar torque_relative = Scalar(0.5);
  Scalar angular_accel_floor_rad_s2 = Scalar(30);

  // The one list of these settings (aloft/settings.hpp).
  template <typename Self, typename Visitor>
  static void visit(Self& s, Visitor&& v) {
    v(s.accel_floor_m_s2, [] {
      return SettingInfo{"release.free_flight.accel_floor_m_s2", "m/s²",
                         "a sample is free while |a - K r| stays under this floor plus the relative part: "
                         "sensor noise and air drag. Set on the generated throws of "
                         "tests/host/test_release_detection.cpp, whose bars hold with it; not swept"};
    });
    v(s.accel_relative, [] {
      return SettingInfo{"release.free_flight.accel_relative", "",
                         "the relative part, times |K r|: an r, a scale factor or a filter 10 % off. Set "
                         "with the floor on the same throws; not swept"};
    });
    v(s.torque_relative, [] {
      return SettingInfo{"release.free_flight.torque_relative", "",
                         "the gyro's torque over its scale above which a torque acts: a tensor 20 % off "
                         "leaves at most about 0.2 of it, a hand that drives the rate about 1 "
                         "(aloft/dynamics/free_flight_residual.hpp); 0.5 lies between. Derived, not swept"};
    });
    v(s.angular_accel_floor_rad_s2, [] {
      return SettingInfo{"release.free_flight.angular_accel_floor_rad_s2", "rad/s²",
                         "noise floor of w_dot from gyro differences, added to the torque's scale so a "
                         "slow spin's noise is no torque. Set on the generated throws; not swept"};
    });
  }
};

// K(w, w_dot) with a = K r: the lever arm's specific force is linear in r.
// K = [w_dot]x + [w]x², written out ([w]x² = w w^T - |w|² I: six products, not a 3x3
// matrix product with its zeros): the same numbers to the bit as forming [w]x and
// [w_dot]x and multiplying (checked on a million random w, w_dot on x86-64 and ARM).
template <typename Scalar>
inline Mat3<Scalar> lever_arm_matrix(const Vec3<Scalar>& w, const Vec3<Scalar>& w_dot) {
  const Scalar xx = w.x() * w.x(), yy = w.y() * w.y(), zz = w.z() * w.z();
  const Scalar xy = w.x() * w.y(), xz = w.x() * w.z(), yz = w.y() * w.z();
  Mat3<Scalar> k;
  k << -(zz + yy), xy - w_dot.z(), xz + w_dot.y(),  //
      xy + w_dot.z(), -(zz + xx), yz - w_dot.x(),   //
      xz - w_dot.y(), yz + w_dot.x(), -(yy + xx);
  return k;
}

// One sample's kinematics in body axes: rate, its derivative, specific force.
template <typename Scalar>
struct BodyKinematics {
  // Left unset: for one that SampleHistory::kinematics fills at once and that is read only
  // when it did (zeroing it first cost every airborne sample ten instructions).
  struct Unset {};
  BodyKinematics() = default;
  explicit BodyKinematics(Unset) : w(), w_dot(), a() {}

  Vec3<Scalar> w = Vec3<Scalar>::Zero();      // rad/s
  Vec3<Scalar> w_dot = Vec3<Scalar>::Zero();  // rad/s²
  Vec3<Scalar> a = Vec3<Scalar>::Zero();      // m/s²
};

// Twice the summed w_dot of samples whose lever-arm matrices K sum to k_sum: K's
// antisymmetric part is [w_dot]x.
template <typename Scalar>
inline Vec3<Scalar> twice_w_dot_sum(const Mat3<Scalar>& k_sum) {
  const Mat3<Scalar>& k = k_sum;
  return Vec3<Scalar>(k(2, 1) - k(1, 2), k(0, 2) - k(2, 0), k(1, 0) - k(0, 1));
}

// Twice the summed torque-free residual, 2 sum(I w_dot + w x (I w)), of samples whose
// lever-arm matrices K sum to k_sum (in I's units per second squared): K's antisymmetric
// part is [w_dot]x and its symmetric part S = w w^T - |w|² 1, and w x (I w) is linear in
// w w^T (integrated_gyroscopic_torque; the multiple of 1 in S adds nothing), so K's sum
// gives the residual's sum exactly, not the residual at a mean w.
template <typename Scalar>
ALOFT_COLD Vec3<Scalar> twice_torque_residual(const Mat3<Scalar>& inertia, const Mat3<Scalar>& k_sum) {
  return integrated_body_torque(inertia, twice_w_dot_sum(k_sum), Mat3<Scalar>(k_sum + k_sum.transpose()));
}

// The largest specific force at the centre of mass that still counts as free flight for
// lever arm r (m/s²): the floor plus a fraction of the lever arm's own specific force.
template <typename Scalar>
inline Scalar free_flight_accel_limit(const FreeFlightSettings<Scalar>& s, const BodyKinematics<Scalar>& k,
                                      const Vec3<Scalar>& r) {
  return s.accel_floor_m_s2 + s.accel_relative * (lever_arm_matrix(k.w, k.w_dot) * r).norm();
}

// |a - K r|: the specific force at the centre of mass (m/s²), zero in free flight.
template <typename Scalar>
inline Scalar centre_specific_force(const BodyKinematics<Scalar>& k, const Vec3<Scalar>& r) {
  return (k.a - lever_arm_matrix(k.w, k.w_dot) * r).norm();
}

// Both of the above from one product K r: what a detector forms per sample.
template <typename Scalar>
struct ResidualAndLimit {
  Scalar residual;  // |a - K r| (m/s²)
  Scalar limit;     // free_flight_accel_limit (m/s²)
};
template <typename Scalar>
inline ResidualAndLimit<Scalar> residual_and_limit(const FreeFlightSettings<Scalar>& s,
                                                   const BodyKinematics<Scalar>& k, const Vec3<Scalar>& r) {
  const Vec3<Scalar> kr = lever_arm_matrix(k.w, k.w_dot) * r;
  return {(k.a - kr).norm(), s.accel_floor_m_s2 + s.accel_relative * kr.norm()};
}

// The gyro's torque over its scale: near 0 in free flight (up to the tensor's error),
// near 1 while an outside torque drives the rate.
// The scale's floor, |I| times the w_dot noise floor: constant for a body, so a detector
// forms it once (torque_scale_floor) and passes it on every sample.
template <typename Scalar>
inline Scalar torque_scale_floor(const FreeFlightSettings<Scalar>& s, const Mat3<Scalar>& inertia) {
  return inertia.norm() * s.angular_accel_floor_rad_s2;
}
template <typename Scalar>
ALOFT_OUT_OF_LINE Scalar relative_torque(const Mat3<Scalar>& inertia, Scalar scale_floor,
                                         const BodyKinematics<Scalar>& k) {
  const Vec3<Scalar> iw_dot = inertia * k.w_dot;
  const Vec3<Scalar> iw = inertia * k.w;
  const Vec3<Scalar> torque = iw_dot + k.w.cross(iw);
  const Scalar scale = iw_dot.norm() + k.w.norm() * iw.norm() + scale_floor;
  return torque.norm() / scale;
}
// The same for a body with a rotor (SPEC §2 rotor) whose momentum h and rate ḣ come from
// its logged speed: the torque left is I (ω̇ − ω̇_gyrostat), with ω̇_gyrostat from Euler's
// equations of the body with its rotor (aloft/dynamics/euler_equations.hpp), which is
// I ω̇ + ω × (I ω + h) + ḣ, less its part along the rotor's axis. That part is ḣ's, and a
// firmware learns the speed late (DShot telemetry: 1-4 ms): at each change of the motor's
// drive (spin-up, the ramp's end, brake, stop) the logged ḣ is off by the rotor's whole
// torque for those milliseconds, which the test took for contact (7 of 270 generated rotor
// throws ended early and gave a false flight, tests/host/test_release_detection.cpp). A
// hand or a landing puts torque across the axis too, and force; ω × h, across the axis, is
// known and stays. A rotor speed off by a fraction leaves about that fraction of
// |ω| |h| + |ḣ|, so the scale takes them beside the body's own terms.
template <typename Scalar>
ALOFT_OUT_OF_LINE Scalar relative_torque(const InertiaTensor<Scalar>& inertia, Scalar scale_floor,
                                         const BodyKinematics<Scalar>& k, const Vec3<Scalar>& rotor_axis,
                                         const Vec3<Scalar>& h, const Vec3<Scalar>& h_dot) {
  const Mat3<Scalar>& tensor = inertia.tensor();
  const Vec3<Scalar> torque = tensor * (k.w_dot - angular_acceleration(inertia, k.w, h, h_dot));
  const Vec3<Scalar> across_axis = torque - torque.dot(rotor_axis) * rotor_axis;
  const Scalar scale = (tensor * k.w_dot).norm() + k.w.norm() * ((tensor * k.w).norm() + h.norm()) +
                       h_dot.norm() + scale_floor;
  return across_axis.norm() / scale;
}

template <typename Scalar>
inline Scalar relative_torque(const FreeFlightSettings<Scalar>& s, const Mat3<Scalar>& inertia,
                              const BodyKinematics<Scalar>& k) {
  return relative_torque(inertia, torque_scale_floor(s, inertia), k);
}

}  // namespace aloft
