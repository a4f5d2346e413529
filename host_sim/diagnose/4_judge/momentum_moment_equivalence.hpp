// When an internal rotor mimics wrong moments, and when it does not (issue 31).
//
// A body of revolution (moments I_t, I_t, I_a about its axis e) with a rotor h = h_a e
// along the axis: I·dw/dt + w × (I·w + h_a e) = 0. Since w × (I_t w) = 0,
//   I·dw/dt = -((I_a - I_t) w_a + h_a) (w × e).
// Its axial part is zero (w × e is normal to e), so w_a is constant over the flight, and the
// transverse part is that of a rotor-free body of revolution whose axial moment is
//   I_a' = I_a + h_a / w_a.
// So within one flight the rotor and the changed axial moment are the same motion exactly
// (and so is any common scale of the moments, which torque-free motion cannot fix). The
// conditions: the body is a body of revolution, h lies along its axis, and w_a is not 0.
// A transverse part of h, or two moments that differ, break it; and across flights thrown
// at different w_a the axial moment that mimics one h differs (h_a / w_a): a session
// shares one h, never one moment change, which is where a rotor is named.
#pragma once

#include <Eigen/Core>

#include <optional>

#include "diagnose/2_model/nominal_inertia.hpp"

namespace aloft::host::diagnose {

// The principal moments (the nominal's ascending order) of the rotor-free body that moves
// as `nominal` with the rotor `h` (body axes) does, for a flight whose rate along the
// symmetry axis is `axial_rate`; none when the conditions above do not hold (within
// `relative` of the moments and of |h|).
std::optional<Eigen::Vector3d> moments_mimicking_momentum(const NominalInertia& nominal,
                                                          const Eigen::Vector3d& h, double axial_rate,
                                                          double relative = 1e-9);

}  // namespace aloft::host::diagnose
