// The torque-free body of the body file with one candidate effect added, and the sensor
// that reads it: what a flight's readings would be for a given initial rate and effect
// parameters. This is the forward model every fit of the diagnosis inverts.
//
// The model (theta, compounds) is effect_model.hpp's; the body's steps are
// flight_dynamics.hpp's, the walks through the samples reading_walks.hpp's.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/effect_model.hpp"
#include "diagnose/2_model/read_samples.hpp"

namespace aloft::host::diagnose {

// How a prediction steps through samples closer together than its longest step (5 ms):
// one integration step over several, the readings between interpolated (the model every
// fit uses), or one step a sample (how it was until issue 30, 1.6x the work at 1 kHz;
// kept as the benchmark's peer and the tests' reference).
enum class SampleStepping { shared_steps, step_per_sample };

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

}  // namespace aloft::host::diagnose
