// Named built-in throws (`aloft study --throw NAME`):
//  - built-in: the defaults of study/synthetic_throw.hpp, argued there; the numbers in
//    the README's study section come from it;
//  - paper: the throw inferred from the paper's GF and CP rows alone by
//    `aloft study --calibrate-to-paper` (study/paper_calibration.hpp), so that the
//    Monte Carlo rows it gives are a prediction of the paper's, not a fit to them.
#pragma once

#include <string>

#include "study/synthetic_throw.hpp"

namespace aloft::host {

// Throws aloft::host::Error for an unknown name.
SyntheticThrowSettings throw_preset(const std::string& name);

}  // namespace aloft::host
