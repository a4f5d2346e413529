// Release and landing from an accelerometer. A thrown body is in free fall, so a
// body-mounted accelerometer reads |a| near 0 (plus the centripetal term w^2 r of its
// offset from the centre of mass, which sets how low the threshold may go); landing is
// a spike far above 1 g. Release needs several consecutive free-fall samples, so one
// noisy sample during the throw does not start a flight.
#pragma once

#include <cstdint>

#include "aloft/dynamics/rotation.hpp"

namespace aloft {

enum class FlightPhase : std::uint8_t { waiting_for_release, airborne, landed };

template <typename Scalar>
struct FlightDetectorSettings {
  Scalar free_fall_below_m_s2 = Scalar(3.0);  // |a| below this counts as free fall
  Scalar landing_above_m_s2 = Scalar(30.0);   // |a| above this while airborne is landing
  std::uint16_t release_samples = 3;          // consecutive free-fall samples for release
};

template <typename Scalar>
class FlightDetector {
 public:
  explicit FlightDetector(const FlightDetectorSettings<Scalar>& settings = {}) : settings_(settings) {}

  // Feeds one accelerometer sample (m/s², sensor axes); returns the phase after it.
  // A non-finite sample is ignored (the phase stays as it was).
  FlightPhase update(const Vec3<Scalar>& accel) {
    if (!all_finite(accel)) return phase_;
    const Scalar a2 = accel.squaredNorm();
    const Scalar fall = settings_.free_fall_below_m_s2;
    const Scalar land = settings_.landing_above_m_s2;
    switch (phase_) {
      case FlightPhase::waiting_for_release:
        run_ = (a2 < fall * fall) ? static_cast<std::uint16_t>(run_ + 1) : std::uint16_t(0);
        if (run_ >= settings_.release_samples) phase_ = FlightPhase::airborne;
        break;
      case FlightPhase::airborne:
        if (a2 > land * land) phase_ = FlightPhase::landed;
        break;
      case FlightPhase::landed: break;
    }
    return phase_;
  }

  FlightPhase phase() const { return phase_; }
  void reset() {
    phase_ = FlightPhase::waiting_for_release;
    run_ = 0;
  }

 private:
  FlightDetectorSettings<Scalar> settings_;
  FlightPhase phase_ = FlightPhase::waiting_for_release;
  std::uint16_t run_ = 0;
};

}  // namespace aloft
