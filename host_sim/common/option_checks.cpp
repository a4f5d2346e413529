#include "common/option_checks.hpp"

#include <filesystem>
#include <string>

#include <unistd.h>

namespace aloft::host {
namespace {

namespace fs = std::filesystem;

bool writable(const fs::path& p) { return ::access(p.c_str(), W_OK) == 0; }

// The folder a new entry at `p` goes into ("." for a bare name).
fs::path parent_of(const fs::path& p) {
  const fs::path parent = p.parent_path();
  return parent.empty() ? fs::path(".") : parent;
}

std::string check_output_folder(const std::string& text);

// A missing folder is made when the file is written (write_file_atomically), as --plot
// makes its folder, so only an existing file, or the nearest existing folder, can refuse.
std::string check_output_file(const std::string& text) {
  const fs::path p(text);
  std::error_code ec;
  if (text.empty()) return "an empty path";
  if (fs::is_directory(p, ec)) return text + " is a folder; give a file name";
  if (fs::exists(p, ec)) return writable(p) ? "" : text + " is not writable";
  const std::string folder_problem = check_output_folder(parent_of(p).string());
  return folder_problem.empty() ? "" : text + ": " + folder_problem;
}

std::string check_output_folder(const std::string& text) {
  std::error_code ec;
  if (text.empty()) return "an empty path";
  fs::path p(text);
  if (fs::exists(p, ec) && !fs::is_directory(p, ec)) {
    return text + " exists and is not a folder";
  }
  // The nearest part of the path that exists must be a folder we may write into.
  while (!fs::exists(p, ec)) {
    const fs::path up = parent_of(p);
    if (up == p) break;
    p = up;
  }
  if (!fs::is_directory(p, ec)) return text + ": " + p.string() + " is not a folder";
  if (!writable(p)) return text + ": folder " + p.string() + " is not writable";
  return "";
}

std::string check_whole_number(const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) {
    return text + " is not a whole number >= 0";
  }
  return "";
}

}  // namespace

CLI::Validator whole_number() { return CLI::Validator(check_whole_number, "", "whole number"); }
CLI::Validator output_file() { return CLI::Validator(check_output_file, "", "output file"); }
CLI::Validator output_folder() { return CLI::Validator(check_output_folder, "", "output folder"); }

}  // namespace aloft::host
