// What `aloft study --calibrate-to-paper` writes: calibration.json (the throw found in
// each frame, how it was searched, and every row beside the paper's, marked fitted or
// predicted) and the same rows as a table for the console.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "study/paper_calibration.hpp"

namespace aloft::host {

nlohmann::json calibration_json(const CalibrationResult& result, const CalibrationSettings& settings);
std::string calibration_table(const CalibrationResult& result);

}  // namespace aloft::host
