// A rotor's angular momentum h read off the gyro by the balance of the Euler equations
// (internal_momentum's start away from zero; 3_fit/effect_fit.cpp, lower_from_readings).
//
// A gyrostat of the nominal tensor I obeys, sample by sample,
//   w × h = r,  r = -(I dw/dt + w × I w),
// with w the body rate read and dw/dt its central difference. Linear in h: the least
// squares h solves sum (|w|² 1 - w wᵀ) h = sum r × w over every usable sample of every
// flight. Within one flight spun about a single axis the component of h along it is not
// fixed (w × h does not see it): a small ridge keeps the system solvable and that
// component near zero, for the fit to find.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/nominal_inertia.hpp"

namespace aloft::host::diagnose {

// internal_momentum's theta (I_nom⁻¹ h, rad/s) that balances the flights' readings best;
// zero where they hold no sample to difference.
Eigen::VectorXd momentum_theta_from_readings(const std::vector<const Flight*>& flights,
                                             const NominalInertia& nominal);

}  // namespace aloft::host::diagnose
