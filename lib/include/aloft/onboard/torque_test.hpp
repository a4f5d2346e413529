// The release detector's torque test (aloft/onboard/release_detector.hpp): how much torque
// from outside the gyro sees at a sample, relative to its scale
// (aloft/dynamics/free_flight_residual.hpp, relative_torque). Two kinds, chosen when the
// pipeline is built (OnboardPipeline's RotorSupport):
//  - BodyTorqueTest: the body alone, torque-free in flight.
//  - GyrostatTorqueTest: a body that may carry a rotor whose speed comes with the samples
//    (SPEC §2 rotor). The rotor's torque on the body, −ḣ − ω × h, is known from the logged
//    speed, so it is part of the model and never taken for a hand or a landing; its part
//    along the rotor's axis, which late telemetry gets wrong at every change of the drive,
//    is left out (free_flight_residual.hpp). Without a rotor in the settings, or where a
//    sample of the span carries no speed, the test is the body's alone, to the bit.
#pragma once

#include <cstdint>

#include "aloft/dynamics/free_flight_residual.hpp"
#include "aloft/dynamics/inertia_tensor.hpp"
#include "aloft/dynamics/rotor.hpp"
#include "aloft/onboard/sample_history.hpp"

namespace aloft {

template <typename Scalar>
class BodyTorqueTest {
 public:
  static constexpr bool knows_rotor = false;

  // The tensor is held, not copied: it must outlive the test.
  BodyTorqueTest(const FreeFlightSettings<Scalar>& s, const Mat3<Scalar>& inertia)
      : inertia_(inertia), scale_floor_(torque_scale_floor(s, inertia)) {}
  BodyTorqueTest(const FreeFlightSettings<Scalar>&, Mat3<Scalar>&&) = delete;

  // Sample i's torque over its scale, with its kinematics k (over +-half samples).
  template <int N>
  Scalar relative(const SampleHistory<Scalar, N>&, std::uint32_t, std::uint32_t,
                  const BodyKinematics<Scalar>& k) const {
    return relative_torque(inertia_, scale_floor_, k);
  }
  const Mat3<Scalar>& inertia() const { return inertia_; }
  Scalar scale_floor() const { return scale_floor_; }

 private:
  const Mat3<Scalar>& inertia_;
  Scalar scale_floor_;  // of the tensor and the settings (free_flight_residual.hpp)
};

template <typename Scalar, int N>
class GyrostatTorqueTest {
 public:
  static constexpr bool knows_rotor = true;
  using Speeds = RotorSpeedHistory<Scalar, N, true>;

  // The tensor, the rotor and its speeds are held, not copied (the pipeline's own): they
  // must outlive the test.
  GyrostatTorqueTest(const FreeFlightSettings<Scalar>& s, const InertiaTensor<Scalar>& inertia,
                     const Rotor<Scalar>& rotor, const Speeds& speeds)
      : inertia_(inertia),
        rotor_(rotor),
        speeds_(speeds),
        scale_floor_(torque_scale_floor(s, inertia.tensor())) {}
  GyrostatTorqueTest(const FreeFlightSettings<Scalar>&, InertiaTensor<Scalar>&&, const Rotor<Scalar>&,
                     const Speeds&) = delete;

  Scalar relative(const SampleHistory<Scalar, N>& history, std::uint32_t i, std::uint32_t half,
                  const BodyKinematics<Scalar>& k) const {
    RotorMomentum<Scalar> m;
    if (!rotor_.present() || !speeds_.momentum(history, i, half, rotor_, m)) {
      return relative_torque(inertia_.tensor(), scale_floor_, k);
    }
    return relative_torque(inertia_, scale_floor_, k, rotor_.axis, m.h, m.h_dot);
  }

 private:
  const InertiaTensor<Scalar>& inertia_;
  const Rotor<Scalar>& rotor_;
  const Speeds& speeds_;
  Scalar scale_floor_;
};

}  // namespace aloft
