// The torque-free body of the body file with one candidate effect added, and the sensor
// that reads it: what a flight's readings would be for a given initial rate and effect
// parameters. This is the forward model every fit of the diagnosis inverts.
//
// Effect parameters (theta), scaled so that a unit change is of the order of one rad/s
// in the readings, which keeps the least-squares problem well conditioned:
//   inertia_moments     u0, u1: moments n_i exp(u_i) (u2 = -u0-u1) along the nominal
//                       principal axes, rescaled to the nominal sum (gyro data and the
//                       torque-free equations cannot fix the scale)
//   inertia_axes        rotation vector d (rad, body axes): I = R(d) I_nom R(d)^T
//   aero_torque         p = k / I_mean (1/rad): tau = -k |w| w
//   internal_damping    a, b: rotor J = 0.9 I_min logistic(a), coupling c = J exp(b)
//   impulse             dw (rad/s): angular impulse I_nom dw (body axes) at impulse_time_s
//   gyro_bias           b (rad/s, sensor axes)
//   gyro_scale          s (sensor axes)
//   sensor_misalignment rotation vector m (rad): sensor->body becomes q_imu * exp(m)
//   clock_drift         eps: a recorded time t maps to true time t_ref + (t - t_ref)/(1+eps)
//
// A compound model (stepwise selection, stepwise_selection.hpp) adds `effect` to the
// effects of `base`: theta holds the base effects' parameters in their order, then
// those of `effect`. Wrong moments act before rotated axes (the rotation turns the
// re-weighted tensor); the sensor effects compose as scale(rotate(w)) + bias.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "diagnose/nominal_inertia.hpp"
#include "diagnose/effect.hpp"
#include "diagnose/flight.hpp"

namespace aloft::host::diagnose {

struct EffectModel {
  EffectModel() = default;
  EffectModel(Effect effect_, const NominalInertia& nominal_, double impulse_time_s_ = 0.0,
              std::vector<Effect> base_ = {})
      : effect(effect_), nominal(nominal_), impulse_time_s(impulse_time_s_), base(std::move(base_)) {}

  Effect effect = Effect::none;
  NominalInertia nominal;
  double impulse_time_s = 0.0;  // impulse only (in effect or in base)
  std::vector<Effect> base;     // effects already in the model; their parameters come first
};

// Every effect of the model, base first, `none` left out.
std::vector<Effect> model_effects(const EffectModel& model);

// Where an effect's parameters start in theta (-1: not in the model).
int theta_offset(const EffectModel& model, Effect effect);

// Parameters of the whole model (the sum over its effects).
int model_parameter_count(const EffectModel& model);

// The sample whose rate is the fitted initial state: the middle of the flight, where a
// sensitive (intermediate-axis) motion is best conditioned both ways; the first sample
// for internal damping, whose rotor is taken to co-rotate with the body at release.
std::size_t reference_index(Effect effect, const Flight& flight);
// The same for a compound model (the first sample when any of its effects is damping).
std::size_t compound_reference_index(const EffectModel& model, const Flight& flight);

// Readings predicted at every sample of `flight`, in the frame of flight.omega, for the
// body rate `omega_ref` (body axes) at sample `ref` and effect parameters `theta`.
void predict_readings(const EffectModel& model, const Flight& flight, std::size_t ref,
                      const Eigen::Vector3d& omega_ref, const Eigen::VectorXd& theta,
                      std::vector<Eigen::Vector3d>& readings);

// The body rate (body axes) that the nominal sensor would read as `reading`; the
// starting guess of the initial state.
Eigen::Vector3d body_rate_of_reading(const Flight& flight, const Eigen::Vector3d& reading);

// The body rate whose reading, under the effect's sensor model, is `reading` (the
// inverse of the sensor part; inertia and torque effects read the body rate as is).
Eigen::Vector3d body_rate_for_reading(const EffectModel& model, const Flight& flight,
                                      const Eigen::VectorXd& theta, const Eigen::Vector3d& reading);

// Physical parameters of the effect for a theta (SPEC §4 keys are made from these).
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
  double k_N_m_s2 = 0.0;                                       // aero_torque
  double rotor_J_kg_m2 = 0.0, c_N_m_s = 0.0;                   // internal_damping
  Eigen::Vector3d vector = Eigen::Vector3d::Zero();  // impulse N·m·s, bias rad/s, scale
  double time_s = 0.0;                               // impulse
  double rate_error = 0.0;                           // clock_drift
};
// Of `model.effect` (its slice of theta).
EffectParameters effect_parameters(const EffectModel& model, const Eigen::VectorXd& theta);
// For principal axis i (columns of `axes`, body axes), the body axis it lies nearest:
// a permutation, chosen greedily by the largest |cosine|.
std::array<int, 3> nearest_body_axes(const Eigen::Matrix3d& axes);

// Of one effect of a compound model.
EffectParameters effect_parameters(const EffectModel& model, const Eigen::VectorXd& theta, Effect effect);

}  // namespace aloft::host::diagnose
