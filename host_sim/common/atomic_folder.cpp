#include "common/atomic_folder.hpp"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include <fcntl.h>
#include <unistd.h>

#include "common/commands.hpp"

namespace aloft::host {

namespace fs = std::filesystem;

namespace {

const std::string kNewTag = ".aloft-new.";
const std::string kOldTag = ".aloft-old.";

std::string sibling(const fs::path& dir, const std::string& tag) {
  return (dir.parent_path() / ("." + dir.filename().string() + tag + std::to_string(::getpid()))).string();
}

// The PID that ends `name` after `tag` (the whole rest must be digits), or 0.
long pid_after(const std::string& name, const std::string& tag) {
  const std::size_t at = name.rfind(tag);
  if (at == std::string::npos || at + tag.size() == name.size()) return 0;
  const std::string digits = name.substr(at + tag.size());
  if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) return 0;
  return std::stol(digits);
}

bool process_alive(long pid) {
  return pid == ::getpid() || ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

// `dir` as an absolute path without a trailing "." or "/" (so it has a file name).
fs::path normal_folder(const std::string& dir) {
  fs::path p = fs::absolute(dir).lexically_normal();
  if (!p.has_filename()) p = p.parent_path();
  return p;
}

// Exchanges two existing folders in one step; false where the file system cannot.
bool exchange(const std::string& a, const std::string& b) {
#ifdef RENAME_EXCHANGE
  if (::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0) return true;
  if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP) {
    throw Error(b + ": cannot swap in the new output folder (" + std::strerror(errno) + ")");
  }
#endif
  (void)a;
  (void)b;
  return false;
}

void rename_or_throw(const std::string& from, const std::string& to) {
  if (std::rename(from.c_str(), to.c_str()) != 0) {
    throw Error(to + ": cannot move the output folder into place (" + std::strerror(errno) + ")");
  }
}

// Moves the complete folder `fresh` to `dir`, and the old `dir` (if any) out of the way.
void swap_in(const std::string& fresh, const std::string& dir, const std::string& old) {
  if (!fs::exists(dir)) return rename_or_throw(fresh, dir);
  if (exchange(fresh, dir)) {
    std::error_code ignored;
    fs::remove_all(fresh, ignored);  // now the old content
    return;
  }
  rename_or_throw(dir, old);  // a kill between these two: the next run puts `old` back
  rename_or_throw(fresh, dir);
  std::error_code ignored;
  fs::remove_all(old, ignored);
}

// Hard-links into `fresh` what `old` holds and `fresh` does not (folders recursively).
void carry_over(const fs::path& old, const fs::path& fresh) {
  for (const auto& entry : fs::directory_iterator(old)) {
    const fs::path target = fresh / entry.path().filename();
    if (fs::exists(fs::symlink_status(target))) continue;  // written by this run
    if (entry.is_symlink()) {
      fs::copy_symlink(entry.path(), target);
    } else if (entry.is_directory()) {
      fs::copy(entry.path(), target,
               fs::copy_options::recursive | fs::copy_options::create_hard_links |
                   fs::copy_options::copy_symlinks);
    } else {
      fs::create_hard_link(entry.path(), target);
    }
  }
}

bool holds_working_directory(const fs::path& dir) {
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  const fs::path real = fs::weakly_canonical(dir, ec);
  if (ec) return false;
  const auto mismatch = std::mismatch(real.begin(), real.end(), cwd.begin(), cwd.end());
  return mismatch.first == real.end();
}

}  // namespace

void clean_after_killed_runs(const std::string& dir_name) {
  const fs::path dir = normal_folder(dir_name);
  const std::string prefix = "." + dir.filename().string();
  std::error_code ec;
  // Old folders first: one may have to become `dir` again before the new ones go.
  for (const std::string& tag : {kOldTag, kNewTag}) {
    for (const auto& entry : fs::directory_iterator(dir.parent_path(), ec)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind(prefix + tag, 0) != 0) continue;
      const long pid = pid_after(name, tag);
      if (pid == 0 || name.size() != prefix.size() + tag.size() + std::to_string(pid).size() ||
          process_alive(pid)) {
        continue;
      }
      std::error_code ignored;
      if (tag == kOldTag && !fs::exists(dir)) {
        fs::rename(entry.path(), dir, ignored);
      } else {
        fs::remove_all(entry.path(), ignored);
      }
    }
  }
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const long pid = pid_after(entry.path().filename().string(), ".tmp.");
    std::error_code ignored;
    if (pid != 0 && entry.is_regular_file(ignored) && !process_alive(pid)) fs::remove(entry.path(), ignored);
  }
}

void replace_folder_atomically(const std::string& dir_name,
                               const std::function<void(const std::string&)>& fill) {
  const fs::path dir = normal_folder(dir_name);
  std::error_code ec;
  fs::create_directories(dir.parent_path(), ec);
  if (holds_working_directory(dir)) {
    fs::create_directories(dir, ec);
    return fill(dir.string());
  }
  const std::string fresh = sibling(dir, kNewTag);
  fs::remove_all(fresh, ec);
  if (!fs::create_directory(fresh, ec)) {
    throw Error(dir.string() + ": cannot create the output folder" + (ec ? " (" + ec.message() + ")" : ""));
  }
  try {
    fill(fresh);
    if (fs::is_directory(dir)) carry_over(dir, fresh);
    swap_in(fresh, dir.string(), sibling(dir, kOldTag));
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(fresh, ec);
    throw Error(dir.string() + ": cannot replace the output folder (" + e.code().message() + ")");
  } catch (...) {
    fs::remove_all(fresh, ec);
    throw;
  }
}

}  // namespace aloft::host
