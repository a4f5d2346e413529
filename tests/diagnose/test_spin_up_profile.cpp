// The spin-up's profile (2_model/spin_up_profile.hpp) against its definition: a first-order
// speed loop, tau ds/dt = r - s, following a set-point r that ramps from 0 to 1 over R.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "diagnose/2_model/spin_up_profile.hpp"

using aloft::host::diagnose::SpinUpProfile;

namespace {

double set_point(const SpinUpProfile& p, double u) {
  if (u <= 0.0) return 0.0;
  return p.rise_s > 0.0 ? std::min(u / p.rise_s, 1.0) : 1.0;
}

}  // namespace

TEST_CASE("the spin-up profile is a speed loop's response to a ramped set-point", "[spin_up_profile]") {
  for (const SpinUpProfile p : {SpinUpProfile{0.0, 0.05, 0.0}, SpinUpProfile{0.0, 0.05, 0.12},
                                SpinUpProfile{0.0, 0.004, 0.2}, SpinUpProfile{0.0, 0.3, 0.01}}) {
    CAPTURE(p.time_constant_s, p.rise_s);
    CHECK(p.level(0.0) == 0.0);
    CHECK(p.level(-0.01) == 0.0);
    CHECK(p.slope(-0.01) == 0.0);
    for (double u = 0.001; u < 2.0; u += 0.00731) {
      CAPTURE(u);
      // The loop's equation, exactly.
      CHECK(p.time_constant_s * p.slope(u) == Approx(set_point(p, u) - p.level(u)).margin(1e-12));
      // The slope is the level's rate of change (a central difference, away from the ramp's end).
      const double d = 1e-6;
      if (std::abs(u - p.rise_s) > 2.0 * d)
        CHECK(p.slope(u) == Approx((p.level(u + d) - p.level(u - d)) / (2.0 * d)).epsilon(1e-5).margin(1e-6));
    }
    // Continuous across the ramp's end; at speed long after.
    CHECK(p.level(p.rise_s + 1e-12) == Approx(p.level(p.rise_s)).margin(1e-9));
    CHECK(p.level(p.rise_s + 40.0 * p.time_constant_s) == Approx(1.0).margin(1e-12));
  }
}

TEST_CASE("the spin-up profile holds the first-order step and the ramp as its limits", "[spin_up_profile]") {
  const SpinUpProfile step{0.0, 0.05, 0.0}, near_step{0.0, 0.05, 1e-9}, near_ramp{0.0, 1e-7, 0.15};
  for (double u = 0.001; u < 0.5; u += 0.0137) {
    CAPTURE(u);
    CHECK(step.level(u) == 1.0 - std::exp(-u / 0.05));
    CHECK(step.slope(u) == std::exp(-u / 0.05) / 0.05);
    CHECK(near_step.level(u) == Approx(step.level(u)).margin(1e-7));
    CHECK(near_ramp.level(u) == Approx(std::min(u / 0.15, 1.0)).margin(1e-6));
  }
}

TEST_CASE("a spin-up before the data is at speed at the first sample", "[spin_up_profile]") {
  // within 1e-6 of speed: ln(1e6) = 13.8 time constants after the ramp's end.
  CHECK(SpinUpProfile{-0.205, 0.0006, 0.0}.at_speed_before_data());
  CHECK_FALSE(SpinUpProfile{-0.205, 0.0006, 0.2}.at_speed_before_data());
  CHECK(SpinUpProfile{-0.3, 0.0006, 0.2}.at_speed_before_data());
  CHECK_FALSE(SpinUpProfile{0.05, 0.04, 0.0}.at_speed_before_data());
  CHECK(SpinUpProfile{-0.3, 0.0006, 0.2}.level(0.3) >= 1.0 - 1e-6);
  CHECK(SpinUpProfile{0.0, 0.05, 0.1}.rise_time_s() == Approx(0.15));
}
