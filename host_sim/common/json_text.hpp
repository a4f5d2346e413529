// A report as text: JSON indented by 2, with any string that is not valid UTF-8 (a marker
// label or a path in another encoding, a damaged file's bytes) written with U+FFFD where
// its bad bytes were, instead of nlohmann::json's type_error 316 ending the command. Valid
// strings are written as they are.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace aloft::host {

// Json: nlohmann::json or nlohmann::ordered_json.
template <typename Json>
std::string json_text(const Json& value) {
  return value.dump(2, ' ', false, Json::error_handler_t::replace);
}

}  // namespace aloft::host
