// The theta of a rotor a motor spins up (effects/internal_momentum_spin_up.cpp), shared by
// the descriptor and the start read off the readings: (I_nom^-1 h_inf [3], rad/s: the body
// rate that would carry the wheel's final momentum; t0 / kSpinUpStartUnit_s, the motor's
// start after the flight's first sample; ln(tau / kSpinUpTimeConstantUnit_s)), each scaled
// so that a unit change moves the readings by about a rad/s or less.
#pragma once

namespace aloft::host::diagnose {

constexpr int kSpinUpParameters = 5;
constexpr double kSpinUpStartUnit_s = 0.1;
constexpr double kSpinUpTimeConstantUnit_s = 0.05;

}  // namespace aloft::host::diagnose
