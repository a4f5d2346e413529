#include "python/json_to_python.hpp"

#include <cmath>
#include <string>

namespace py = pybind11;

namespace aloft::host::python {
namespace {

// Valid UTF-8 as it is; otherwise what json.loads reads of the string as the report's
// text writes it (nlohmann's error_handler_t::replace).
template <typename Json>
py::object string_to_python(const std::string& text) {
  PyObject* decoded = PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "strict");
  if (decoded != nullptr) return py::reinterpret_steal<py::object>(decoded);
  PyErr_Clear();
  const std::string written = Json(text).dump(-1, ' ', false, Json::error_handler_t::replace);
  return py::module_::import("json").attr("loads")(written);
}

template <typename Json>
py::object convert(const Json& value) {
  switch (value.type()) {
    case Json::value_t::null: return py::none();
    case Json::value_t::boolean: return py::bool_(value.template get<bool>());
    case Json::value_t::number_integer: return py::int_(value.template get<std::int64_t>());
    case Json::value_t::number_unsigned: return py::int_(value.template get<std::uint64_t>());
    case Json::value_t::number_float: {
      const double number = value.template get<double>();
      return std::isfinite(number) ? py::object(py::float_(number)) : py::object(py::none());
    }
    case Json::value_t::string: return string_to_python<Json>(value.template get_ref<const std::string&>());
    case Json::value_t::array: {
      py::list list(value.size());
      std::size_t i = 0;
      for (const Json& element : value) list[i++] = convert(element);
      return std::move(list);
    }
    case Json::value_t::object: {
      py::dict dict;
      for (auto it = value.begin(); it != value.end(); ++it)
        dict[string_to_python<Json>(it.key())] = convert(*it);
      return std::move(dict);
    }
    case Json::value_t::binary:
    case Json::value_t::discarded: break;
  }
  return py::none();  // no report holds binary or discarded values
}

}  // namespace

py::object to_python(const nlohmann::json& value) { return convert(value); }
py::object to_python(const nlohmann::ordered_json& value) { return convert(value); }

}  // namespace aloft::host::python
