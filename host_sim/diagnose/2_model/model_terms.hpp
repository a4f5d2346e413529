// The terms of the forward model (flight_model.hpp) that effects change: the body's
// dynamics (tensor, drag, rotor, a rate jump), the sensor (rotation, scale, bias) and
// the clock. They start as the nominal model; each effect of a model sets or composes
// its own terms from its slice of theta (its descriptor's `apply`), and the integrator
// and sensor model read them. An effect that needs a term not listed here adds it here
// and to flight_dynamics.hpp's steps.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/2_model/spin_up_profile.hpp"

namespace aloft::host::diagnose {

struct ModelTerms {
  explicit ModelTerms(const NominalInertia& nominal) : inertia(nominal.tensor) {}

  Eigen::Matrix3d inertia;  // kg·m², body axes (before the rotor is taken out)
  double drag = 0.0;        // tau = -drag |w| w, N·m·s²
  double rotor = 0.0;       // rotor J, kg·m² (0: rigid body)
  double rotor_rate = 0.0;  // coupling c / J, 1/s
  // An internal rotor's angular momentum (a gyrostat), fixed in body axes, N·m·s:
  // I·dw/dt + w × (I·w + momentum) = 0.
  Eigen::Vector3d momentum = Eigen::Vector3d::Zero();
  // A rotor a motor spins up during the flight, about a body-fixed axis: h(t) =
  // spin_up_momentum s(t) with the profile's s (its start after the flight's first sample),
  // adding h(t) x w and the motor's reaction -dh/dt to the torque (spin_up_walk.hpp).
  // Zero: none.
  Eigen::Vector3d spin_up_momentum = Eigen::Vector3d::Zero();
  SpinUpProfile spin_up_profile;
  bool has_jump = false;                           // an impulse at the model's impulse_time_s
  Eigen::Vector3d jump = Eigen::Vector3d::Zero();  // rad/s; angular impulse I_nom * jump
  bool misaligned = false;                         // sensor->body becomes q_imu * misalignment
  Eigen::Quaterniond misalignment = Eigen::Quaterniond::Identity();
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();  // reading_i = scale_i (R^T w)_i + bias_i
  Eigen::Vector3d bias = Eigen::Vector3d::Zero();   // rad/s, sensor axes
  double time_factor = 1.0;                         // true time elapsed per recorded second
};

}  // namespace aloft::host::diagnose
