// Physical parameters of a fitted effect, in the units a user reads (SPEC §4 `params`
// keys are made from these). Each effect's descriptor fills the fields it owns from its
// slice of theta (flight_model.hpp) and reads them back for the report and the bars.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <vector>

#include "diagnose/2_model/nominal_inertia.hpp"
#include "diagnose/2_model/spin_up_profile.hpp"

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
  // internal_momentum spun up by a motor (`vector`: its final h): its profile (the start
  // after the flight's first sample), and the end of the data it describes (seconds after
  // the first sample: the flight's, or a session's longest), where the report gives h (set
  // by the flow; 0: unknown, h at the end read as the final h).
  bool spin_up = false;
  SpinUpProfile spin_up_profile;
  double spin_up_end_s = 0.0;
  // The body file's rotor as the log gives it at that end (Flight::logged_rotor_h_N_m_s; set
  // by the flow): what the report sets beside the h it found.
  std::optional<Eigen::Vector3d> spin_up_logged_h;
  // h at spin_up_end_s.
  Eigen::Vector3d spin_up_h_at_end() const { return spin_up_h_at(vector, spin_up_profile, spin_up_end_s); }
  // A session's pooled fit, which shares the wheel's axis only: each flight's own profile
  // (empty: one flight, or a fit that shares every parameter). The fields above are then
  // the longest flight's (set by the flow with the flights' ends).
  struct SpinUpFlight {
    Eigen::Vector3d final_h = Eigen::Vector3d::Zero();
    SpinUpProfile profile;
    double end_s = 0.0;
    std::optional<Eigen::Vector3d> logged_h;  // Flight::logged_rotor_h_N_m_s (set by the flow)
    Eigen::Vector3d h_at_end() const { return spin_up_h_at(final_h, profile, end_s); }
  };
  std::vector<SpinUpFlight> spin_up_flights;

  // h of a spin-up to `final_h` with `profile`, at `end_s` (0: unknown, read as the final h).
  static Eigen::Vector3d spin_up_h_at(const Eigen::Vector3d& final_h, const SpinUpProfile& profile,
                                      double end_s) {
    if (!(end_s > 0.0)) return final_h;
    const double u = end_s - profile.start_s;
    return u <= 0.0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(profile.level(u) * final_h);
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
