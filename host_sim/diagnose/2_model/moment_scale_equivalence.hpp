// When a gyro scale error mimics wrong moments, and when it does not (issue 9).
//
// Read by a gyro whose axes are the principal axes, a body with moments I' moves as
// w_i' = a'_i w_j w_k, with a'_1 = (I'_2 - I'_3)/I'_1 and cyclic. Scaled readings
// v_i = c_i w_i obey the nominal equations v_i' = a_i v_j v_k exactly when
// c_j c_k / c_i = a'_i / a_i for every i, i.e. c_i = sqrt(r_i / (r_1 r_2 r_3)) with
// r_i = a_i / a'_i: the nominal body's rates v, read with gains 1 + s_i = 1 / c_i, are the
// wrong body's rates w. So a scale reproduces wrong moments exactly when
// every r_i is positive: the nominal moments are distinct (no a_i is zero) and the wrong
// ones keep their order (each a'_i has the sign of a_i).
//
// Not the reverse: a tensor's coefficients satisfy a_1 + a_2 + a_3 + a_1 a_2 a_3 = 0, so
// only scales whose implied coefficients keep that identity are mimicked by moments. And
// never on a body of revolution: there a_3 = 0, and moments that break the symmetry make
// a'_3 non-zero, which no scale reproduces.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>

namespace aloft::host::diagnose {

// The scale errors s (gains 1 + s along the principal axes) that make the nominal body
// read like a body with `moments`; none when no scale can.
std::optional<Eigen::Vector3d> scale_mimicking_moments(const Eigen::Vector3d& nominal_moments,
                                                       const Eigen::Vector3d& moments);

// Whether the gyro's axes lie along the principal axes (in any order and sign), the other
// condition for a scale to act on the principal rates one by one.
bool gyro_along_principal_axes(const Eigen::Quaterniond& principal_axes,
                               const Eigen::Quaterniond& sensor_to_body);

}  // namespace aloft::host::diagnose
