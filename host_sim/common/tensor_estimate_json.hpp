// A flight's own tensor estimate (aloft/onboard/tensor_estimate.hpp) as `aloft replay` and
// `aloft records` report it (SPEC §5 `tensor_estimate`): ratios, axes and, with a rotor,
// absolute moments, each with its 95 % interval as [low, high]; null where the flight does
// not give it, with a note.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "aloft/onboard/tensor_estimate.hpp"
#include "aloft/records/flight_record.hpp"

namespace aloft::host {

nlohmann::json tensor_estimate_json(const TensorEstimate<float>& e);

// The estimate a version 3 flight record keeps, as the pipeline reported it (the
// quaternion's w from its x, y, z).
TensorEstimate<float> tensor_estimate_of(const FlightRecordTensor& t);

// One line for the terminal: "I1/I3 0.4641 ± 0.0012, I2/I3 ...", or why there is none.
std::string tensor_estimate_text(const TensorEstimate<float>& e);

}  // namespace aloft::host
