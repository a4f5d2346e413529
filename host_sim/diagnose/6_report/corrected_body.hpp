// A corrected body file: the user's own body file with its inertia replaced by the tensor
// the verdict fitted, so that the answer to "is my tensor right?" comes with the tensor
// to use instead. Everything else in the file (name, mass, markers, imu) is kept.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace aloft::host::diagnose {

// The first `tensor_kg_m2` among the verdict's effects (inertia_moments, inertia_axes),
// or null when the verdict changes no moment and no axis.
nlohmann::json fitted_tensor(const nlohmann::json& report);

// Writes `body_path`'s JSON with "inertia": {"tensor": fitted} to `out_path` (whole or not
// at all). Returns false, writing nothing, when the report fits no tensor.
bool write_corrected_body(const std::string& body_path, const nlohmann::json& report,
                          const std::string& out_path);

// The same from the body file's text, for a body handed over in memory.
bool write_corrected_body_from_text(const std::string& body_text, const nlohmann::json& report,
                                    const std::string& out_path);

}  // namespace aloft::host::diagnose
