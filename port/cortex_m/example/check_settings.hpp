// The onboard-check configuration the example firmware runs and the host reference
// repeats in double precision: both must agree for the comparison test to mean anything.
#pragma once

#include "aloft/onboard/onboard_check.hpp"

namespace aloft_example {

constexpr int live_simulations = 8;          // K
constexpr unsigned seed_every_samples = 10;  // N

template <typename Scalar>
aloft::OnboardCheckSettings<Scalar> check_settings() {
  aloft::OnboardCheckSettings<Scalar> settings;
  settings.seed_every = static_cast<decltype(settings.seed_every)>(seed_every_samples);
  return settings;  // gyro aligned with body axes; no accelerometer in the recording
}

}  // namespace aloft_example
