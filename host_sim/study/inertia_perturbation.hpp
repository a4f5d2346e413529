// The Monte Carlo tensors of the seed study: the nominal (GF) tensor with its principal
// moments and/or principal axes changed by a random amount within a bound.
//
// How a draw is made (uniform within the bound, as the paper says):
//  - moments, bound b %: each nominal principal moment I_i becomes I_i (1 + u_i b/100)
//    with u_1, u_2, u_3 independent and uniform in [-1, 1];
//  - axes, bound b degrees: the principal axes are rotated from their nominal directions
//    by R = exp(r), with the rotation vector r drawn uniformly in the ball |r| <= b
//    (uniform in volume: rejection sampling from the cube). A rotation by angle |r|
//    moves no axis by more than |r| and moves the axes perpendicular to r by exactly
//    |r|, so the ball is exactly the set of rotations that keep every principal axis
//    within b of its nominal (CCS) axis, the paper's "within ±b from the respective CCS
//    axes". Unlike three Cardan angles each in ±b, it favours no axis and no sequence,
//    and it never exceeds the bound (three Cardan angles of 10° reach a 17° rotation);
//  - both: moments and axes drawn independently, each as above, with the same bound.
// Common random numbers: a draw always takes the same numbers from its stream (three
// uniforms for the moments, then the ball point), whatever the family and bound, and the
// study gives simulation i of every Monte Carlo analysis the same stream. Each analysis
// is still uniform within its own bound; across analyses the draws are paired (the same
// seed sample and the same unit perturbation, scaled by the bound), so differences
// between bounds and families are differences of the tensor, not of sampling luck.
// A draw that breaks the triangle inequality (impossible for a real body) is drawn
// again; it cannot happen for the paper's cylinder and its bounds.
#pragma once

#include <string>

#include "aloft/inertia_tensor.hpp"
#include "study/simulation_random.hpp"

namespace aloft::host {

enum class PerturbationFamily { moments, axes, both };

const char* family_name(PerturbationFamily family);  // "moments", "axes", "both"
const char* family_unit(PerturbationFamily family);  // "%" or "deg"

struct InertiaPerturbation {
  PerturbationFamily family = PerturbationFamily::moments;
  double bound = 0.0;  // percent for moments; degrees for axes; both: the same number
};

// The nominal tensor perturbed by one random draw within `perturbation`. The nominal's
// principal moments are perturbed along its own principal axes, and those axes are then
// rotated in body axes. Throws std::runtime_error if no valid tensor is found in 1000 draws.
InertiaTensor<double> draw_perturbed_inertia(const InertiaTensor<double>& nominal,
                                             const InertiaPerturbation& perturbation,
                                             SimulationRandom& random);

}  // namespace aloft::host
