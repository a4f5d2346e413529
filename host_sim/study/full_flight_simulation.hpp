// One simulation of the seed study: seeded from the state sampled at index k, integrated
// forward to the end of the flight and backward to its start (RK4, aloft/rk4_integrator),
// the two halves joined, and compared with the measured angular velocity sample by
// sample (StudyFlight says how for pose and rate flights). Returns the RMS deviation
// angle, degrees. Nothing is stored: each comparison is made as the step is taken.
#pragma once

#include <cstddef>

#include <vector>

#include "aloft/lanes/batch_flight.hpp"
#include "aloft/dynamics/inertia_tensor.hpp"
#include "study/da_frame.hpp"
#include "study/study_flight.hpp"

namespace aloft::host {

// RMS DA (degrees) in body and world axes of the full-flight simulation with `inertia`
// seeded at sample k. A rate flight has no world frame: NaN there.
RmsDaByFrame full_flight_rms_da_deg(const StudyFlight& flight, const InertiaTensor<double>& inertia,
                                    std::size_t k);

// The same simulations several at once, in SIMD lanes (aloft/lanes/batch_flight.hpp, xsimd):
// the same numbers as full_flight_rms_da_deg within 1e-9 degrees (a test checks it).
// The flight is flattened once into the arrays the lanes gather from.
class LaneFlight {
 public:
  explicit LaneFlight(const StudyFlight& flight);
  LaneFlight(const LaneFlight&) = delete;  // arrays_ points into this object's vectors
  LaneFlight& operator=(const LaneFlight&) = delete;
  const FlightArrays<double>& arrays() const { return arrays_; }

 private:
  std::vector<double> time_, orientation_, state_omega_, measured_body_, measured_world_;
  FlightArrays<double> arrays_;
};

// How many simulations run side by side on this machine: 8 with AVX-512, 4 with AVX2
// and FMA, else 2 (SSE2).
std::size_t simulation_lanes();

// RMS DA per frame of sims[0 .. count), count <= simulation_lanes().
void full_flight_rms_da_deg_lanes(const LaneFlight& flight, const FlightSimulation<double>* sims,
                                  std::size_t count, RmsDaByFrame* out);

// The axis of the rotation from orientation a to orientation b, in a's body axes, scaled
// by sin(angle/2): the vector part of a^-1 b on the short side. It points along
// log(a^-1 b) = omega dt (aloft::omega_body_from_orientations), and a deviation angle
// needs only that direction, so the simulation loop skips the log's atan2 and division
// (a test checks both give the same RMS DA).
Eigen::Vector3d rotation_axis_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

// The same axis in world axes: the vector part of b a^-1 on the short side (a's body
// axis rotated by a), pointing along omega_world dt.
Eigen::Vector3d world_rotation_axis_between(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

// Checks a flight before thousands of simulations run on it: at least 3 samples,
// increasing times, finite unit orientations, finite non-zero measured rates. Throws
// aloft::host::Error naming the flight and the sample.
void validate_study_flight(const StudyFlight& flight);

}  // namespace aloft::host
