// Python arguments as a command's options, checked by the command's own CLI11 rules and
// messages: a keyword `name` is the option --name, with `_` for `-` (odr_hz is --odr-hz);
// its value a word (a str, a path, a number, written as Python writes it, which reads
// back as the same double), a list or tuple of them (joined by commas, as
// --pose-columns takes them), True (a flag given), or False and None (not given). A
// line the command refuses raises ValueError with the line the command prints.
#pragma once

#include <pybind11/pybind11.h>

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace aloft::host::python {

class CommandLine {
 public:
  explicit CommandLine(const std::string& command);

  // Where the command's options are registered (add_diagnose_options, ...).
  CLI::App& command() { return *command_; }

  void add_positional(pybind11::handle value);
  void add_option(const std::string& keyword, pybind11::handle value);
  void add_options(const pybind11::kwargs& keywords);

  // Parses the words into the registered options; throws Error on a refused line.
  void parse();

 private:
  CLI::App app_;
  CLI::App* command_;
  std::vector<std::string> words_;
  std::vector<std::string> positionals_;  // after "--", so that none is taken for an option
};

// A path argument as text (str, bytes or os.PathLike).
std::string path_text(pybind11::handle path);

// A body argument: a body file's path, or a dict of a body file's content (arrays and
// NumPy numbers in it are taken as their lists and numbers). Returns the name the body
// goes by in messages (its path, or "body dict") and sets *json_text to the dict as JSON
// text (empty for a path).
std::string body_argument(pybind11::handle body, std::string* json_text);

}  // namespace aloft::host::python
