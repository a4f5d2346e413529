// What a flight controller's first-order gyro filters do to the motion they pass, beyond a
// delay: a filter whose impulse response has mean m and variance v turns a slow rate x into
// x(t - m) + (v / 2) x'' to second order. The delay a torque-free fit absorbs in its initial
// rate (the motion shifted in time is a motion too); the bend it cannot: behind a PT1 at 50 Hz
// or two at 4 kHz it left each flight a misfit of its own, and flights that share a rotor
// disagreed (scatter 3.9 and 7.9 where 1 +- 0.4 is due; bent, 1.6 and 0.7:
// docs/validation/diagnose-accuracy.md). The prediction bends its readings by the bend of the
// low-pass the noise floor fitted (Flight::gyro_filter_bend_s2, LowPassShape::bend_s2).
#pragma once

#include <Eigen/Core>

#include <vector>

#include "diagnose/1_input/flight.hpp"
#include "diagnose/2_model/read_samples.hpp"

namespace aloft::host::diagnose {

// Adds gyro_filter_bend_s2 times the readings' second derivative to each sample `read` wants
// (none where it is 0). The derivative is the three-point one over kBendSpan either side among
// those samples, so the cubic pieces the readings are interpolated with between integration
// steps (reading_walks.hpp) do not show; within each run of them with no step longer than
// kBendSpan (a fold's chunk, a flight), at its ends that of the nearest sample kBendSpan
// inside. Only the samples read: a fit that reads half of them pays nothing more.
void bend_by_gyro_filter(const Flight& flight, std::vector<Eigen::Vector3d>& readings, ReadSamples read = {});

}  // namespace aloft::host::diagnose
