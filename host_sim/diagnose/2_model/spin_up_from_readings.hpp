// Where a rotor a motor spins up (effects/internal_momentum_spin_up.cpp) starts its fit:
// read off the gyro by the balance of the Euler equations, as momentum_from_readings.hpp
// reads a steady rotor. With the body rate w read and its central difference dw/dt,
//   -(I dw/dt + w x I w) = s(t) w x h_inf + s'(t) h_inf  (s: spin_up_profile.hpp),
// linear in h_inf for a given profile (t0, tau, R): a 3x3 least-squares problem for each
// point of a grid of motor starts (t0 from before release to the middle of the shortest
// flight, every 10 ms), time constants (20-160 ms) and set-point ramps (5-200 ms), the
// flights' own clocks starting at their first samples; the point with the least misfit
// gives the start. A fit from zero cannot find the profile: with no rotor it moves nothing.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/nominal_inertia.hpp"

namespace aloft::host::diagnose {

// The spin-up's theta (internal_momentum_spin_up.cpp's layout) the flights' readings
// give; zero where they give none.
Eigen::VectorXd spin_up_theta_from_readings(const std::vector<const Flight*>& flights,
                                            const NominalInertia& nominal);

}  // namespace aloft::host::diagnose
