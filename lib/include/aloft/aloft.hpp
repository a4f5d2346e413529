// Everything in lib/, for callers who want one include. The folders follow the data:
//   dynamics/  rigid-body physics: tensors, rotations, Euler's equations, integrators, DA
//   lanes/     the same dynamics in SIMD lanes, for the host's batches of simulations
//   sensor/    the ICM-42688-P: registers, FIFO decode, driver, the sample stream's clock
//   onboard/   release window -> lever arm -> check: the flight pipeline
//   records/   flight records, their CRC and byte order, and the ring that stores them
// status.hpp and cold_path.hpp are the conventions every folder uses; settings.hpp says how
// every settings struct lists its settings once.
#pragma once

#include "aloft/cold_path.hpp"
#include "aloft/settings.hpp"
#include "aloft/status.hpp"

#include "aloft/dynamics/angular_velocity.hpp"
#include "aloft/dynamics/deviation.hpp"
#include "aloft/dynamics/euler_equations.hpp"
#include "aloft/dynamics/free_flight_residual.hpp"
#include "aloft/dynamics/inertia_tensor.hpp"
#include "aloft/dynamics/principal_dynamics.hpp"
#include "aloft/dynamics/principal_frame.hpp"
#include "aloft/dynamics/rigid_body_state.hpp"
#include "aloft/dynamics/rk4_integrator.hpp"
#include "aloft/dynamics/rotation.hpp"
#include "aloft/dynamics/splitting_integrator.hpp"
#include "aloft/dynamics/symmetric_eigen.hpp"

#include "aloft/lanes/batch_flight.hpp"
#include "aloft/lanes/lane_angle.hpp"
#include "aloft/lanes/lane_rotation.hpp"
#include "aloft/lanes/lanes.hpp"

#include "aloft/sensor/icm42688p_driver.hpp"
#include "aloft/sensor/icm42688p_fifo.hpp"
#include "aloft/sensor/icm42688p_registers.hpp"
#include "aloft/sensor/imu_bus.hpp"
#include "aloft/sensor/imu_sample.hpp"
#include "aloft/sensor/stream_clock.hpp"
#include "aloft/sensor/whole_microseconds.hpp"

#include "aloft/onboard/lever_arm_estimate.hpp"
#include "aloft/onboard/lever_arm_estimator.hpp"
#include "aloft/onboard/onboard_check.hpp"
#include "aloft/onboard/onboard_pipeline.hpp"
#include "aloft/onboard/release_detector.hpp"
#include "aloft/onboard/release_window.hpp"
#include "aloft/onboard/sample_history.hpp"
#include "aloft/onboard/torque_test.hpp"

#include "aloft/records/block_device.hpp"
#include "aloft/records/crc32.hpp"
#include "aloft/records/flight_record.hpp"
#include "aloft/records/flight_record_from_result.hpp"
#include "aloft/records/little_endian.hpp"
#include "aloft/records/record_ring.hpp"
#include "aloft/records/settings_hash.hpp"
