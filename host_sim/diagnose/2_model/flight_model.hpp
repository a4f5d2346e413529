// The torque-free body of the body file with one candidate effect added, and the sensor
// that reads it: what a flight's readings would be for a given initial rate and effect
// parameters. This is the forward model every fit of the diagnosis inverts.
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

#include "diagnose/2_model/effect.hpp"
#include "diagnose/2_model/effect_parameters.hpp"
#include "diagnose/1_input/flight.hpp"
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

// How a prediction steps through samples closer together than its longest step (5 ms):
// one integration step over several, the readings between interpolated (the model every
// fit uses), or one step a sample (how it was until issue 30, 1.6x the work at 1 kHz;
// kept as the benchmark's peer and the tests' reference).
enum class SampleStepping { shared_steps, step_per_sample };

// The samples whose readings a caller reads: those whose flag is set in both arrays (a
// fit's training mask and the flight's usable flags, one entry a sample). A prediction
// leaves the others between its steps at zero instead of interpolating them (a fold fit
// compares half the samples: case00 380.7 -> 377.0 M instructions); the steps, and so every
// reading it does make, are the same. Null: every sample.
struct ReadSamples {
  const char* mask = nullptr;
  const char* usable = nullptr;
  bool wanted(std::size_t k) const { return mask == nullptr || (mask[k] != 0 && usable[k] != 0); }
};

// Readings predicted at every sample of `flight`, in the frame of flight.omega, for the
// body rate `omega_ref` (body axes) at sample `ref` and effect parameters `theta`.
// `rate_at_impulse` (optional): set to the body rate where the walk from the reference
// meets the impulse, before it is applied (left alone when no walk meets it). `read`:
// the samples wanted (ReadSamples), by default all.
void predict_readings(const EffectModel& model, const Flight& flight, std::size_t ref,
                      const Eigen::Vector3d& omega_ref, const Eigen::VectorXd& theta,
                      std::vector<Eigen::Vector3d>& readings,
                      SampleStepping stepping = SampleStepping::shared_steps,
                      Eigen::Vector3d* rate_at_impulse = nullptr, ReadSamples read = {});

// predict_readings of two reference rates under one theta, readings_a for omega_a and
// readings_b for omega_b, bit for bit the same. Where the reference is the first or last
// sample (a rotor's release) each prediction has one walk, and the two run side by side
// in the two lanes of the paired steps; elsewhere they are predicted one after the other.
void predict_readings_pair(const EffectModel& model, const Flight& flight, std::size_t ref,
                           const Eigen::Vector3d& omega_a, const Eigen::Vector3d& omega_b,
                           const Eigen::VectorXd& theta, std::vector<Eigen::Vector3d>& readings_a,
                           std::vector<Eigen::Vector3d>& readings_b, ReadSamples read = {});

// predict_readings of (omega_a, theta_a) and of (omega_b, theta_b), bit for bit the same.
// Where the reference is the first or last sample and the two bodies have the same kind
// of terms (a rotor's differenced theta columns), the two walks run side by side in the
// two lanes of the paired steps, each lane with its own body's terms; else as
// predict_readings_pair (one theta) or one after the other.
void predict_readings_two(const EffectModel& model, const Flight& flight, std::size_t ref,
                          const Eigen::Vector3d& omega_a, const Eigen::VectorXd& theta_a,
                          const Eigen::Vector3d& omega_b, const Eigen::VectorXd& theta_b,
                          std::vector<Eigen::Vector3d>& readings_a, std::vector<Eigen::Vector3d>& readings_b,
                          ReadSamples read = {});

// The theta directions (1: yes) along which only the sensor's terms move (bias, scale,
// rotation): the readings' derivatives along them need no simulation.
std::vector<char> sensor_directions(const EffectModel& model, const Eigen::VectorXd& theta);

// d readings / d theta_i for each direction i that `directions` marks (from
// sensor_directions), from `readings`, the prediction at theta: the reading is
// scale (R w) + bias, so the rate w behind each reading is differentiated through the
// sensor alone. `columns`: 3n rows (sample k at 3k) and a column per theta entry at
// least, sized by the caller (the fitter's Jacobian): each marked column is written, the
// others are left as they are (no matrix of every theta column zeroed: case00
// 407.1 -> 405.0 M instructions).
void sensor_reading_derivatives(const EffectModel& model, const Flight& flight, const Eigen::VectorXd& theta,
                                const std::vector<Eigen::Vector3d>& readings,
                                const std::vector<char>& directions, Eigen::MatrixXd& columns);

// The theta directions (1: yes) along which only the impulse's jump moves.
std::vector<char> impulse_directions(const EffectModel& model, const Eigen::VectorXd& theta);

// d readings / d theta_i for each impulse direction i that `directions` marks, without
// simulating: beyond the impulse (on the far side from `ref`), a change of the jump is a
// change of the rate where the walk met it, carried on by the same flow map as a change
// of omega_ref. `jacobian`: 3n rows (in any weighting: the result has the same), one
// column per theta entry and then d readings / d omega_ref, three; `impulse_rate_derivative`:
// d rate_at_impulse / d omega_ref (predict_readings). Each marked theta column is written
// in place (zero on the near side), the others are left as they are: the fitter's
// Jacobian takes them as they come, with no matrix of every theta column zeroed and then
// copied (case00 421.3 -> 409.0 M instructions).
void impulse_reading_derivatives(const EffectModel& model, const Flight& flight, std::size_t ref,
                                 const Eigen::VectorXd& theta, const Eigen::Matrix3d& impulse_rate_derivative,
                                 const std::vector<char>& directions, Eigen::MatrixXd& jacobian);

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
