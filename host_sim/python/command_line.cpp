#include "python/command_line.hpp"

#include <algorithm>

#include "common/commands.hpp"
#include "common/usage_error.hpp"

namespace py = pybind11;

namespace aloft::host::python {
namespace {

std::string word(py::handle value) {
  if (py::isinstance<py::str>(value) || py::isinstance<py::bytes>(value) ||
      py::hasattr(value, "__fspath__")) {
    return path_text(value);
  }
  if (py::isinstance<py::bool_>(value)) return py::cast<bool>(value) ? "true" : "false";
  // int, float and NumPy numbers: str() is the shortest text that reads back the same.
  if (py::isinstance<py::int_>(value) || py::isinstance<py::float_>(value) || py::hasattr(value, "dtype")) {
    return py::str(value);
  }
  throw py::type_error("expected a str, a path, a number or a list of them, not " +
                       std::string(py::str(value.get_type().attr("__name__"))));
}

bool is_list(py::handle value) {
  return py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value) ||
         (py::hasattr(value, "ndim") && py::cast<int>(value.attr("ndim")) > 0);
}

}  // namespace

std::string path_text(py::handle path) { return py::str(py::module_::import("os").attr("fsdecode")(path)); }

CommandLine::CommandLine(const std::string& command) : app_("", "aloft") {
  command_ = app_.add_subcommand(command, "");
  words_ = {"aloft", command};
}

void CommandLine::add_positional(py::handle value) { positionals_.push_back(word(value)); }

void CommandLine::add_option(const std::string& keyword, py::handle value) {
  if (value.is_none()) return;
  std::string name = "--" + keyword;
  std::replace(name.begin(), name.end(), '_', '-');
  if (py::isinstance<py::bool_>(value)) {
    if (py::cast<bool>(value)) words_.push_back(name);
    return;
  }
  words_.push_back(name);
  if (!is_list(value)) {
    words_.push_back(word(value));
    return;
  }
  std::string joined;
  for (py::handle element : value) joined += (joined.empty() ? "" : ",") + word(element);
  words_.push_back(joined);
}

void CommandLine::add_options(const py::kwargs& keywords) {
  for (const auto& [key, value] : keywords) add_option(py::cast<std::string>(key), value);
}

void CommandLine::parse() {
  std::vector<std::string> words = words_;
  if (!positionals_.empty()) words.push_back("--");
  words.insert(words.end(), positionals_.begin(), positionals_.end());
  std::vector<const char*> argv;
  for (const std::string& w : words) argv.push_back(w.c_str());
  try {
    app_.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError& e) {
    throw Error(usage_error_line(app_, e));
  }
}

std::string body_argument(py::handle body, std::string* json_text) {
  json_text->clear();
  if (!py::isinstance<py::dict>(body)) return path_text(body);
  // Arrays and NumPy numbers in the dict (a tensor as np.ndarray) as their lists and numbers.
  const py::cpp_function plain([](py::handle value) -> py::object {
    if (py::hasattr(value, "tolist")) return value.attr("tolist")();
    throw py::type_error("body dict: a value of type " +
                         std::string(py::str(value.get_type().attr("__name__"))) + " is not JSON");
  });
  *json_text =
      py::cast<std::string>(py::module_::import("json").attr("dumps")(body, py::arg("default") = plain));
  return "body dict";
}

}  // namespace aloft::host::python
