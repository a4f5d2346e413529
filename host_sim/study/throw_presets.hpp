// Named built-in throws (`aloft study --throw NAME`):
//  - built-in: the defaults of study/synthetic_throw.hpp, argued there; the numbers in
//    docs/study.md come from it;
//  - paper-body, paper-world: the throws inferred from the paper's GF and CP rows alone,
//    with DA in body or in world axes, by `aloft study --calibrate-to-paper`
//    (study/paper_calibration.hpp), so that the Monte Carlo rows they give are a
//    prediction of the paper's, not a fit to them. Each belongs with its own frame.
#pragma once

#include <string>

#include "study/synthetic_throw.hpp"

namespace aloft::host {

// Throws aloft::host::Error for an unknown name.
SyntheticThrowSettings throw_preset(const std::string& name);

}  // namespace aloft::host
