// What the STM32F405 firmware checks and how: the body's inertia tensor, K, and the
// onboard pipeline's settings. A maker sets the tensor to their own body's (from its body
// file, SPEC §2); the one here is the practice brick (data/practice/case00/body.json). The
// build checks and decomposes it (flight_inertia below).
#pragma once

#include "aloft/onboard/onboard_pipeline.hpp"

namespace aloft_stm32f405 {

constexpr int live_simulations = 8;  // K

// kg m², body axes about the centre of mass.
constexpr float inertia_kg_m2[3][3] = {
    {0.002823489583f, 0.0f, 0.0f},
    {0.0f, 0.009669583333f, 0.0f},
    {0.0f, 0.0f, 0.010873489583f},
};

// The practice brick has no rotor: the image keeps no rotor speeds (RotorSupport::none).
// The flight image estimates each flight's tensor; the images built with
// ALOFT_STM32F405_WITHOUT_TENSOR leave it out, to measure what it costs
// (measure_footprint.cmake).
#if defined(ALOFT_STM32F405_WITHOUT_TENSOR)
constexpr aloft::TensorEstimation tensor_estimation = aloft::TensorEstimation::off;
#else
constexpr aloft::TensorEstimation tensor_estimation = aloft::TensorEstimation::on;
#endif
using Pipeline =
    aloft::OnboardPipeline<float, live_simulations, aloft::RotorSupport::none, tensor_estimation>;

// The tensor is symmetric, so the array reads the same in row or column order.
inline aloft::Mat3<float> body_tensor() { return Eigen::Map<const aloft::Mat3<float>>(&inertia_kg_m2[0][0]); }

// The tensor as make_from_tensor checks and decomposes it, done at build time on the build
// machine (port/host_tools/bake_flight_inertia.cpp writes flight_inertia.cpp in the build
// folder; a rejected tensor stops the build), so the image carries no eigen solver.
extern const aloft::InertiaTensorParts<float> flight_inertia_parts;
// The hashes the flight records carry (aloft/records/flight_record_from_result.hpp,
// settings_hash.hpp) of body_tensor() and of pipeline_settings() at K = live_simulations,
// made by the same build-time program: the image links no settings hasher (about 700 B).
extern const std::uint32_t flight_tensor_hash;
extern const std::uint32_t flight_settings_hash;
inline aloft::InertiaTensor<float> flight_inertia() {
  return aloft::InertiaTensor<float>::from_accepted_parts(flight_inertia_parts);
}

inline aloft::OnboardPipelineSettings<float> pipeline_settings() {
  return aloft::OnboardPipelineSettings<float>();  // gyro aligned with body axes
}

}  // namespace aloft_stm32f405
