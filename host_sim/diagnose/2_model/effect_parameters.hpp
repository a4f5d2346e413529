// Physical parameters of a fitted effect, in the units a user reads (SPEC §4 `params`
// keys are made from these). Each effect's descriptor fills the fields it owns from its
// slice of theta (flight_model.hpp) and reads them back for the report and the bars.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <vector>

#include "diagnose/2_model/nominal_inertia.hpp"

namespace aloft::host::diagnose {

struct EffectParameters {
  Eigen::Vector3d principal_kg_m2 = Eigen::Vector3d::Zero();  // inertia_moments (ascending nominal order)
  // Inertia effects, as a user reads them (SPEC §4): the moments in the body file's axis
  // order (entry i: the principal axis nearest body axis i), the nominal ones in the same
  // order, and the whole tensor in body axes.
  Eigen::Vector3d principal_body_order_kg_m2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d nominal_body_order_kg_m2 = Eigen::Vector3d::Zero();
  Eigen::Matrix3d tensor_kg_m2 = Eigen::Matrix3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  // axes / misalignment
  double angle_deg = 0.0;
  double k_N_m_s2 = 0.0;                             // aero_torque
  double rotor_J_kg_m2 = 0.0, c_N_m_s = 0.0;         // internal_damping
  Eigen::Vector3d vector = Eigen::Vector3d::Zero();  // impulse N·m·s, bias rad/s, scale
  double time_s = 0.0;                               // impulse
  double rate_error = 0.0;                           // clock_drift
  // internal_momentum spun up by a motor (`vector`: its final h): when it starts after the
  // flight's first sample, its time constant, and the end of the data it describes
  // (seconds after the first sample: the flight's, or a session's longest), where the
  // report gives h (set by the flow; 0: unknown, h at the end read as the final h).
  bool spin_up = false;
  double spin_up_start_s = 0.0, spin_up_time_constant_s = 0.0, spin_up_end_s = 0.0;
  // h at spin_up_end_s.
  Eigen::Vector3d spin_up_h_at_end() const {
    return spin_up_h_at(vector, spin_up_start_s, spin_up_time_constant_s, spin_up_end_s);
  }
  // A session's pooled fit, which shares the wheel's axis only: each flight's own profile
  // (empty: one flight, or a fit that shares every parameter). The fields above are then
  // the longest flight's (set by the flow with the flights' ends).
  struct SpinUpFlight {
    Eigen::Vector3d final_h = Eigen::Vector3d::Zero();
    double start_s = 0.0, time_constant_s = 0.0, end_s = 0.0;
    Eigen::Vector3d h_at_end() const { return spin_up_h_at(final_h, start_s, time_constant_s, end_s); }
  };
  std::vector<SpinUpFlight> spin_up_flights;

  // Whether a spin-up from `start_s` (after the first sample) with `time_constant_s` is
  // within 1e-6 of its speed at the first sample: the readings then see a steady rotor, not
  // the spin-up, and its time constant is not measured.
  static bool spin_up_before_data(double start_s, double time_constant_s) {
    return start_s <= -std::log(1e6) * time_constant_s;
  }
  // h of a first-order spin-up to `final_h` from `start_s` with `time_constant_s`, at `end_s`
  // (0: unknown, read as the final h).
  static Eigen::Vector3d spin_up_h_at(const Eigen::Vector3d& final_h, double start_s, double time_constant_s,
                                      double end_s) {
    if (!(end_s > 0.0)) return final_h;
    const double u = end_s - start_s;
    return u <= 0.0 ? Eigen::Vector3d::Zero()
                    : Eigen::Vector3d((1.0 - std::exp(-u / time_constant_s)) * final_h);
  }
};

// For principal axis i (columns of `axes`, body axes), the body axis it lies nearest:
// a permutation, chosen greedily by the largest |cosine|.
std::array<int, 3> nearest_body_axes(const Eigen::Matrix3d& axes);

// Fills the user-facing inertia fields (body-order moments, nominal ones, the tensor in
// body axes) from principal moments along `axes` (columns, body axes).
void describe_inertia(EffectParameters& p, const Eigen::Vector3d& moments, const Eigen::Matrix3d& axes,
                      const NominalInertia& nominal);

}  // namespace aloft::host::diagnose
