// A fitted rotation (of the principal axes, or of the sensor) as the report gives it.
// The torque-free motion cannot see a turn of the principal frame about a symmetry
// axis, nor a half turn about a principal axis (the Euler equations are unchanged by
// it), so a fitted rotation is only known up to those: the report gives the smallest
// member.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "diagnose/2_model/effect_parameters.hpp"
#include "diagnose/2_model/nominal_inertia.hpp"

namespace aloft::host::diagnose {

// The smallest rotation that means the same as `r` to the nominal body. `right`: the
// symmetry acts as r * s (a rotated tensor); otherwise as s * r (a rotated sensor).
Eigen::Quaterniond canonical_rotation(const Eigen::Quaterniond& r, const NominalInertia& nominal, bool right);

// Fills p.rotation and p.angle_deg from a rotation vector (rad) `theta`.
void describe_rotation(EffectParameters& p, const Eigen::VectorXd& theta, const NominalInertia& nominal,
                       bool right);

}  // namespace aloft::host::diagnose
