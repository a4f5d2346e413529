// The generator's own flight dynamics: a rigid body with the effects lib/ leaves out.
// Deliberately a separate code path from lib/'s torque-free integrators and from the
// diagnosis's models, so the withheld-effect test checks the diagnosis against an
// independent implementation of the physics.
//
// State: orientation q (body -> world, Hamilton, lib/ conventions), shell angular
// velocity w (body axes) and, for internal damping, the absolute angular velocity of a
// spherical rotor w_r (body axes). Equations, body axes, I_s = I - J·1 the shell's
// inertia (the nominal tensor I is what the body weighs when it moves rigidly):
//   I_s dw/dt   = tau_ext(t, w) - w × (I_s w + h) + c (w_r - w)
//   J dw_r/dt   = -J w × w_r - c (w_r - w)
//   dq/dt       = ½ q ⊗ (0, w)
// with tau_ext = -k |w| w (aerodynamic damping) plus an impulse: a half-sine torque
// pulse fixed in body axes, starting at `impulse_time_s`, lasting
// `impulse_duration_s`, of integral `angular_impulse` (duration 0: an instantaneous
// jump of I_s w by the impulse), and h a steadily spinning internal rotor's angular
// momentum, fixed in body axes (a gyrostat; zero but for internal_momentum). The damping
// rotor exchanges momentum with the shell only, so the total momentum L = I_s w + J w_r is fixed in space
// without external torque while kinetic energy falls at rate c |w_r - w|²: the "spherical rotor in a viscous
// cavity" model of internal damping.
//
// Integration: classical RK4 on the 10-dimensional state with the quaternion
// renormalised, steps no longer than `max_step_s`, and step boundaries placed on every
// requested sample time and on both ends of the impulse pulse.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "rotor_spin_up.hpp"

namespace aloft::generator {

struct FlightPhysics {
  Eigen::Matrix3d inertia_kg_m2 = Eigen::Matrix3d::Identity();  // whole body, rigid
  double aero_k_N_m_s2 = 0.0;
  double rotor_inertia_kg_m2 = 0.0;  // J; 0: no internal damping
  double rotor_damping_N_m_s = 0.0;  // c
  bool has_impulse = false;
  double impulse_time_s = 0.0;
  double impulse_duration_s = 0.0;
  Eigen::Vector3d angular_impulse_N_m_s = Eigen::Vector3d::Zero();  // body axes
  // A rotor spinning at a steady rate inside (a gyrostat): its angular momentum h, fixed
  // in body axes, adds -w × h to the torque and h to the body's angular momentum.
  Eigen::Vector3d internal_momentum_N_m_s = Eigen::Vector3d::Zero();
  // A rotor a motor spins up from rest after release (rotor_spin_up.hpp): h(t) on top of
  // the steady one, and its reaction torque -dh/dt.
  RotorSpinUp spin_up;
};

struct FlightState {
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d omega_body = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotor_omega_body = Eigen::Vector3d::Zero();  // ignored without a rotor
};

class PerturbedRigidBody {
 public:
  explicit PerturbedRigidBody(const FlightPhysics& physics);

  // States at the given times (ascending, >= 0), starting from `initial` at t = 0.
  std::vector<FlightState> sample(const FlightState& initial, const std::vector<double>& times_s,
                                  double max_step_s = 1e-4) const;

  // Total angular momentum in body axes (shell plus rotor), at time t (a spinning-up
  // rotor's h changes; without one t changes nothing).
  Eigen::Vector3d angular_momentum(const FlightState& s, double t = 0.0) const;
  // Total kinetic energy (shell plus rotor).
  double kinetic_energy(const FlightState& s) const;
  // dw/dt of the shell at time t, for the accelerometer's tangential term.
  Eigen::Vector3d shell_angular_acceleration(double t, const FlightState& s) const;

 private:
  struct Derivative {
    Eigen::Vector4d q_dot;  // Eigen coefficient order x, y, z, w
    Eigen::Vector3d w_dot;
    Eigen::Vector3d wr_dot;
  };
  // `side_s`: the instant whose side of a spinning-up rotor's rate steps (its motor's
  // start, a ramp's end) the torque is taken on: a step beside one says on which side it
  // lies; NaN: t's own.
  Derivative derivative(double t, const Eigen::Vector4d& q, const Eigen::Vector3d& w,
                        const Eigen::Vector3d& wr, double side_s = NAN) const;
  Eigen::Vector3d external_torque(double t, const Eigen::Vector3d& w) const;
  void rk4_step(double t, double h, FlightState& s) const;
  void advance(double t0, double t1, double max_step_s, FlightState& s) const;

  FlightPhysics physics_;
  bool has_rotor_;
  Eigen::Matrix3d shell_inertia_;
  Eigen::Matrix3d shell_inverse_;
};

}  // namespace aloft::generator
