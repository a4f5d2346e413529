// A candidate model of the body and its sensor (flight_model.hpp predicts its readings):
// the nominal body of the body file with one candidate effect, or a compound of effects,
// and the layout of their parameters theta.
//
// Effect parameters (theta), scaled so that a unit change is of the order of one rad/s
// in the readings, which keeps the least-squares problem well conditioned: each effect's
// descriptor (effects/<name>.cpp) says what its parameters are and, through the model
// terms it sets (model_terms.hpp), what they do to the body or the sensor.
//
// A compound model (stepwise selection, stepwise_selection.hpp) adds `effect` to the
// effects of `base`: theta holds the base effects' parameters in their order, then
// those of `effect`. Wrong moments act before rotated axes (the rotation turns the
// re-weighted tensor); the sensor effects compose as scale(rotate(w)) + bias.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <utility>
#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/effect.hpp"
#include "diagnose/2_model/effect_parameters.hpp"
#include "diagnose/2_model/model_terms.hpp"
#include "diagnose/2_model/nominal_inertia.hpp"

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

// Whether one of the model's effects acts at an instant the fitter does not take but a
// search finds (descriptor `searched_parameters`: the impulse's time, `impulse_time_s`).
bool has_searched_time(const EffectModel& model);

// Parameters of the whole model (the sum over its effects).
int model_parameter_count(const EffectModel& model);

// The terms of (model, theta): the nominal model's, changed by each of the model's
// effects in turn (an effect that sets the tensor afresh first).
ModelTerms model_terms(const EffectModel& model, const Eigen::VectorXd& theta);

// The sample whose rate is the fitted initial state: the middle of the flight, where a
// sensitive (intermediate-axis) motion is best conditioned both ways; the first sample
// for an effect that `starts_at_release` (internal damping, whose rotor is taken to
// co-rotate with the body at release).
std::size_t reference_index(Effect effect, const Flight& flight);
// The same for a compound model (the first sample when any of its effects starts there).
std::size_t compound_reference_index(const EffectModel& model, const Flight& flight);

// The body rate (body axes) that the nominal sensor would read as `reading`; the
// starting guess of the initial state.
Eigen::Vector3d body_rate_of_reading(const Flight& flight, const Eigen::Vector3d& reading);

// The body rate whose reading, under the effect's sensor model, is `reading` (the
// inverse of the sensor part; inertia and torque effects read the body rate as is).
Eigen::Vector3d body_rate_for_reading(const EffectModel& model, const Flight& flight,
                                      const Eigen::VectorXd& theta, const Eigen::Vector3d& reading);

// Physical parameters (SPEC §4 keys are made from these) of `model.effect` (its slice of
// theta), or of one effect of a compound model.
EffectParameters effect_parameters(const EffectModel& model, const Eigen::VectorXd& theta);
EffectParameters effect_parameters(const EffectModel& model, const Eigen::VectorXd& theta, Effect effect);

}  // namespace aloft::host::diagnose
