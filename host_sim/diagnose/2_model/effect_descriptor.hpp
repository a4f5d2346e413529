// Everything `aloft diagnose` knows about one unmodelled effect, in one place: a
// descriptor per effect (effects/<name>.cpp), registered by one line in
// effects/effect_list.def. The rest of diagnose asks the descriptor and never switches
// on the effect, so adding an effect is: write its file, add its line, and give the report
// its words for the effect's parameters (6_report/effect_words.cpp; docs/diagnose.md,
// "Adding an effect").
//
// Fill in every field; a test (tests/diagnose/test_effect_descriptor.cpp) checks that
// each registered descriptor is complete and its name is a SPEC §4 name.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <string>
#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/effect.hpp"
#include "diagnose/2_model/effect_parameters.hpp"
#include "diagnose/2_model/model_terms.hpp"
#include "diagnose/2_model/nominal_inertia.hpp"

namespace aloft::host::diagnose {

// What the practical-significance bar (practical_significance.hpp) weighs an effect's
// size against.
struct SignificanceScale {
  const NominalInertia* nominal = nullptr;  // null: the bars that need it do not apply
  double speed = 1.0;                       // mean |w| of the data, rad/s, never 0
  double duration_s = 0.0;                  // of the data that informs the parameters
};

// One effect of a fitted model, as the ranking's physics check sees it.
struct FittedSlice {
  Eigen::VectorXd theta;           // the effect's parameters (empty: the fit has none)
  Eigen::VectorXd standard_error;  // of theta (empty: unknown)
  // Physical parameters, when this is the effect the candidate adds (null for an effect
  // already in the model it starts from).
  const EffectParameters* added = nullptr;
};

// What the rest of diagnose asks an effect to do. Every hook is required (a hook with
// nothing to say returns an empty string); listed in this order in each descriptor.
struct EffectHooks {
  // The standard error (theta units) below which a parameter counts as pinned by the data.
  double (*tolerance)(double mean_speed, double duration_s) = nullptr;
  // The model hook: what the effect does to the dynamics or the sensor, for its theta.
  void (*apply)(const Eigen::VectorXd& theta, const NominalInertia& nominal, ModelTerms& terms) = nullptr;
  // Its theta as physical parameters (impulse_time_s: the model's, for an impulse).
  EffectParameters (*parameters)(const Eigen::VectorXd& theta, const NominalInertia& nominal,
                                 double impulse_time_s) = nullptr;
  // Why the effect is too small to matter (practical_significance.hpp); empty: it matters.
  std::string (*too_small)(const EffectParameters& p, const SignificanceScale& scale) = nullptr;
  // Why fitted parameters make no sense for a real sensor (plausibility.hpp); empty: fine.
  std::string (*senseless)(const EffectParameters& p) = nullptr;
  // Why a fit breaks physics (the ranking rules it out); empty: fine.
  std::string (*unphysical)(const FittedSlice& fit) = nullptr;
};

// The largest gyro scale error or clock rate error a descriptor's `senseless` accepts: no
// phone or MEMS gyro is 30 % off, so a fit that needs more mimics another effect
// (4_judge/plausibility.hpp).
constexpr double kLargestSensibleScaleError = 0.30;

// Where the fitter starts an effect whose parameters enter non-linearly and whose
// neutral model is a limit rather than a point (neutral_at_zero false): the cost of each
// start of a grid is looked at first (one simulation each), the best is refined, and the
// best other start within the search window is refined too and reported when it reaches
// another minimum (3_fit/effect_fit_result.hpp, OtherMinimum).
struct StartGrid {
  std::vector<Eigen::VectorXd> (*starts)() = nullptr;  // in the order that breaks a tie
  // Two minima are distinct when a parameter differs by more than this (theta units).
  double distinct = 0.0;
  // The effect's parameters when it joins a compound model (one fit from there, no grid).
  Eigen::VectorXd (*joining)() = nullptr;
};

// An effect this one can stand in for under a condition, never the reverse: a gyro scale
// for wrong moments (2_model/moment_scale_equivalence.hpp). The ranking lists this effect
// beside a verdict of `stands_in_for` only where `holds` for that verdict's fitted
// parameters, and never lists `stands_in_for` beside a verdict of this effect.
struct OneWayEquivalence {
  Effect stands_in_for = Effect::none;  // none: no such effect
  bool (*holds)(const EffectParameters& other, const NominalInertia& nominal,
                const Eigen::Quaterniond& sensor_to_body) = nullptr;
};

// Parameters each flight of a pooled fit has of its own, beside its initial rate, where the
// physics shares only part of an effect: a wheel's axis is the body's, while each throw
// starts and speeds its motor its own way. The pooled fit (3_fit/fit_setup.hpp) shares the
// first `shared_count` entries of theta's parameterisation; each flight's local block is
// its rate then `count` own parameters, and `theta_of` makes that flight's theta (the
// descriptor's `parameter_count` entries, what the model and the report read). own(0) is
// the flight's scale of the shared part (theta_of scales it by exp(own(0))), which the
// shared part could take up as well: the
// session's first flight has it pinned at 0 (the shared part is that flight's), so the
// shared part is fixed by the data. Used for the effect alone, not in a compound model.
struct FlightOwnParameters {
  int count = 0;  // 0: the flights share every parameter
  int shared_count = 0;
  Eigen::VectorXd (*theta_of)(const Eigen::VectorXd& shared, const Eigen::VectorXd& own) = nullptr;
  // A flight's own parameters that, with `shared`, come nearest to `theta` (a start).
  Eigen::VectorXd (*own_of)(const Eigen::VectorXd& theta, const Eigen::VectorXd& shared) = nullptr;
};

struct EffectDescriptor {
  const char* name = nullptr;  // the SPEC §4 name, also the report's
  // Parameters in theta (flight_model.hpp), scaled so that a unit change moves the
  // readings by about one rad/s.
  int parameter_count = 0;
  // Parameters found by search rather than by the fitter, which the ranking charges all
  // the same (the impulse's time).
  int searched_parameters = 0;
  bool sensor = false;             // describes the gyro, not the motion: IMU input only
  bool sets_tensor = false;        // `apply` sets the tensor afresh, so it acts first
  bool starts_at_release = false;  // the fitted initial rate is the first sample's
  bool neutral_at_zero = true;     // theta = 0 is the nominal model
  bool rotation_gauge = false;     // a rotation: turns that change nothing are no parameter
  // Shared by the flights of a session (false: it belongs to one flight, as a knock does,
  // and is fitted per flight only).
  bool shared_by_flights = true;
  // Not started at zero but from a grid (nullptr: zero, or the caller's start).
  const StartGrid* start_grid = nullptr;
  // A start read off the readings, for a fit from zero that can stop in another minimum
  // (3_fit/effect_fit.cpp, lower_from_readings; nullptr: none). Its flights, their
  // nominal tensor; returns the effect's theta.
  Eigen::VectorXd (*start_from_readings)(const std::vector<const Flight*>&, const NominalInertia&) = nullptr;
  // The standard errors the identifiability rule (4_judge/candidate_ranking.cpp) weighs
  // against `tolerance`, from theta and its own (nullptr: theta's own). For a parameter that
  // is the logarithm of a size whose fit may tend to 0 (a spin-up's rise or time constant,
  // where the wheel spins up as a step or a ramp), the size's error in the logarithm's unit:
  // a rise of 2 ms whose logarithm the data leave loose is still a rise of 0-10 ms.
  Eigen::VectorXd (*pinned_errors)(const Eigen::VectorXd& theta,
                                   const Eigen::VectorXd& standard_error) = nullptr;
  // Named only where the data tell it from its look-alikes (4_judge/told_apart.hpp): it
  // beats every other candidate beyond a tie, and in a session the flights' own fits of it
  // agree. For an effect whose few free parameters mimic several others within a flight.
  bool named_only_when_told_apart = false;
  // For such an effect: the effect whose error it takes up within each flight when fitted
  // alone, so that a session's flights disagree on it though they share one value; such a
  // session also tries the two fitted together at its first step
  // (4_judge/joint_candidates.hpp; none: no such effect).
  Effect jointly_with = Effect::none;
  // A variant of another effect, reported under that effect's name (`name` is the same): a
  // rotor whose speed changes beside the steady rotor. Not a candidate of its own: tried at
  // a step where the effect it varies, added to the model there, fits as well as the best
  // of the rest (4_judge/variant_candidates.hpp). none: not a variant.
  Effect variant_of = Effect::none;
  // What of a flight's own fit the flights of a session must agree on (told_apart.hpp,
  // between_flight_scatter.hpp): the part the physics shares, with its covariance and its
  // degrees of freedom (a wheel's axis; each throw starts and speeds its motor its own way).
  // nullptr: every parameter.
  int (*shared_part)(const Eigen::VectorXd& theta, const Eigen::MatrixXd& covariance, Eigen::VectorXd& part,
                     Eigen::MatrixXd& part_covariance) = nullptr;
  // What each flight of a pooled fit has of its own (count 0: nothing but its rate).
  FlightOwnParameters flight_own{};
  // Effects a gyro alone cannot tell from this one whatever the flight (SPEC §4), padded
  // with `none`.
  std::array<Effect, 2> gyro_equivalents{};
  OneWayEquivalence one_way_equivalent{};
  EffectHooks hooks;
};

#define ALOFT_EFFECT(name) extern const EffectDescriptor name##_effect;
#include "diagnose/2_model/effects/effect_list.def"
#undef ALOFT_EFFECT

// The descriptor of a registered effect.
const EffectDescriptor& describe(Effect effect);

// Every registered effect, in registry order (`none` first).
std::vector<Effect> registered_effects();

// Hooks several effects share.
std::string no_objection(const EffectParameters&);
std::string no_physics_objection(const FittedSlice&);

}  // namespace aloft::host::diagnose
