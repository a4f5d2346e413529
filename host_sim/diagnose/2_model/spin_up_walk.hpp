// The readings of a model whose rotor a motor spins up during the flight
// (ModelTerms::spin_up_momentum; effects/internal_momentum_spin_up.cpp):
//   I dw/dt + w x (I w + h(t)) = -dh/dt,  h(t) = h_inf s(t - t0)  (spin_up_profile.hpp).
// The torque depends on time, which the shared-step walks of reading_walks.hpp do not
// carry, so this walk steps RK4 a sample at a time (at most kMaxStep, the walks' longest
// step, per step) from the reference both ways, the motor's start, the end of its
// set-point's ramp and an impulse's instant as step boundaries; each step takes the motor's
// side from its middle (a step's reaction torque jumps from 0 to h_inf / tau at t0). The
// rest of the model (tensor, drag, a steady rotor, a damping rotor, an impulse, the sensor,
// the clock) is FlightDynamics'.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/flight_dynamics.hpp"
#include "diagnose/2_model/model_terms.hpp"
#include "diagnose/2_model/read_samples.hpp"

namespace aloft::host::diagnose {

// Whether the terms hold a rotor that spins up (then predict_readings walks here).
inline bool has_spin_up(const ModelTerms& terms) { return terms.spin_up_momentum.squaredNorm() > 0.0; }

// Readings at every sample of `flight` (those `read` asks for; the others left as they
// are) for body rate `omega_ref` at sample `ref`; `jump_time`: an impulse's instant on the
// walk's clock (FlightDynamics::has_jump).
void predict_spin_up_readings(const FlightDynamics& dynamics, const ModelTerms& terms, const Flight& flight,
                              std::size_t ref, const Eigen::Vector3d& omega_ref, double jump_time,
                              std::vector<Eigen::Vector3d>& readings, ReadSamples read = {});

}  // namespace aloft::host::diagnose
