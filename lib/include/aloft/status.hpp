// Status codes: every fallible call in lib/ returns one instead of throwing, and leaves
// its object's state untouched unless it returns Status::ok.
#pragma once

#include <cstdint>

namespace aloft {

// [[nodiscard]]: a status dropped on the floor is a check skipped; the compiler says so.
enum class [[nodiscard]] Status : std::uint8_t{
    ok = 0,
    non_finite_input,        // a NaN or infinite number was given
    non_positive_time_step,  // dt <= 0 (direction is a separate argument)
    non_unit_quaternion,     // |q| differs from 1 beyond rounding of a stored quaternion
    tensor_not_symmetric,    // I != I^T beyond rounding
    tensor_not_positive_definite,
    tensor_breaks_triangle_inequality,  // some principal moment exceeds the sum of the other two
    invalid_dimension,                  // a mass, length or rate that must be positive is not
    zero_vector,                        // a direction was asked of a zero vector
    not_airborne,                       // no flight to report: none released, or none ended yet
    time_not_increasing,                // a sample's time stamp is not after the previous one
    bus_error,                          // the port's bus call failed
    sensor_not_found,                   // the chip's identity register holds another value
    register_not_kept,                  // a configuration register reads back other than written
    storage_full,                       // no room left where data must be written
    corrupt_data,                       // stored or received bytes fail their check
};

// One short English phrase per status, for logs and the host program's messages.
constexpr const char* describe(Status s) {
  switch (s) {
    case Status::ok: return "ok";
    case Status::non_finite_input: return "non-finite input (NaN or infinity)";
    case Status::non_positive_time_step: return "time step is not positive";
    case Status::non_unit_quaternion: return "quaternion is not of unit length";
    case Status::tensor_not_symmetric: return "inertia tensor is not symmetric";
    case Status::tensor_not_positive_definite: return "inertia tensor is not positive definite";
    case Status::tensor_breaks_triangle_inequality: return "principal moments break the triangle inequality";
    case Status::invalid_dimension: return "a mass, length or rate is not positive";
    case Status::zero_vector: return "zero vector has no direction";
    case Status::not_airborne: return "not airborne";
    case Status::time_not_increasing: return "time stamp is not after the previous one";
    case Status::bus_error: return "bus transfer failed";
    case Status::sensor_not_found: return "sensor not found (identity register holds another value)";
    case Status::register_not_kept: return "a configuration register did not keep its value";
    case Status::storage_full: return "storage is full";
    case Status::corrupt_data: return "data fail their integrity check";
  }
  return "unknown status";
}

}  // namespace aloft
