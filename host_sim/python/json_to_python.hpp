// A report (nlohmann::json) as the Python objects json.loads makes of its text as the
// command writes it (common/json_text.hpp): objects as dicts in the report's key order,
// arrays as lists, integers as int, numbers as float (exact: the text round-trips every
// double), a non-finite number as None (the text's null), and a string that is not valid
// UTF-8 with U+FFFD where the text has it.
#pragma once

#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

namespace aloft::host::python {

pybind11::object to_python(const nlohmann::json& value);
pybind11::object to_python(const nlohmann::ordered_json& value);

}  // namespace aloft::host::python
