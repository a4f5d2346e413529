// The Monte Carlo tensors of the seed study: the nominal (GF) tensor with its principal
// moments and/or principal axes changed by a random amount within a bound.
//
// How a draw is made (uniform within the bound, as the paper says):
//  - moments, bound b %: each nominal principal moment I_i becomes I_i (1 + u_i b/100)
//    with u_1, u_2, u_3 independent and uniform in [-1, 1];
//  - axes, bound b degrees, by one of two samplers (the paper names neither):
//    - ball (the default): the principal axes are rotated from their nominal
//      directions by R = exp(r), with the rotation vector r drawn uniformly in the ball
//      |r| <= b (uniform in volume: rejection sampling from the cube). A rotation by
//      angle |r| moves no axis by more than |r|, so every draw keeps each principal
//      axis within b of its nominal (CCS) axis, the paper's "within ±b from the
//      respective CCS axes", and it favours no axis and no sequence. The ball is only
//      part of the rotations that do so, though: a rotation of 12.26° about
//      (1,1,1)/√3 moves each axis by exactly 10° and lies outside the 10° ball (a test
//      checks this);
//    - cardan: R = Rx(a) Ry(b) Rz(c), three independent angles uniform in ±b, as
//      OpenSim's Cardan coordinates would give. Each angle keeps within the bound, but
//      the rotation reaches 17° at ±10° and an axis may leave its 10° cone;
//  - both: moments and axes drawn independently, each as above, with the same bound.
// Common random numbers: a draw always takes the same numbers from its stream (three
// uniforms for the moments, then the rotation's), whatever the family and bound, and the
// study gives simulation i of every Monte Carlo analysis the same stream. Each analysis
// is still uniform within its own bound; across analyses the draws are paired (the same
// seed sample and the same unit perturbation, scaled by the bound), so differences
// between bounds and families are differences of the tensor, not of sampling luck.
// A draw that breaks the triangle inequality (impossible for a real body) is drawn
// again; it cannot happen for the paper's cylinder and its bounds.
#pragma once

#include <string>

#include "aloft/dynamics/inertia_tensor.hpp"
#include "study/simulation_random.hpp"

namespace aloft::host {

enum class PerturbationFamily { moments, axes, both };
enum class AxesSampler { ball, cardan };

const char* family_name(PerturbationFamily family);  // "moments", "axes", "both"
const char* family_unit(PerturbationFamily family);  // "%" or "deg"
const char* axes_sampler_name(AxesSampler sampler);  // "ball", "cardan"

struct InertiaPerturbation {
  PerturbationFamily family = PerturbationFamily::moments;
  double bound = 0.0;  // percent for moments; degrees for axes; both: the same number
  AxesSampler sampler = AxesSampler::ball;
};

// The nominal tensor perturbed by one random draw within `perturbation`. The nominal's
// principal moments are perturbed along its own principal axes, and those axes are then
// rotated in body axes. Throws std::runtime_error if no valid tensor is found in 1000 draws.
InertiaTensor<double> draw_perturbed_inertia(const InertiaTensor<double>& nominal,
                                             const InertiaPerturbation& perturbation,
                                             SimulationRandom& random);

}  // namespace aloft::host
