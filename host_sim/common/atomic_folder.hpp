// Replacing a whole output folder so that it is, at every moment, all old or all new
// (issue 26): the new content is written into a sibling folder, then swapped in with one
// rename. Siblings and files a killed run left behind are cleaned by the next run.
//
// Names of what a run keeps beside DIR while it works (PID: the writing process):
//   .NAME.aloft-new.PID   the new folder being filled
//   .NAME.aloft-old.PID   the old folder just swapped out, about to be removed
// and inside a folder, NAME.tmp.PID: one file being written (common/atomic_file.hpp).
#pragma once

#include <functional>
#include <string>

namespace aloft::host {

// Removes what runs killed while writing `dir` left behind: the siblings above and the
// NAME.tmp.PID files directly inside `dir`, those of processes no longer alive. When a
// run died between the two renames of the portable swap (so `dir` is missing), the old
// folder is put back: `dir` is then all old.
void clean_after_killed_runs(const std::string& dir);

// Replaces `dir` (created if missing, with its parents) by a folder whose files `fill`
// writes: `fill` is given the path of the new sibling folder. Whatever the old `dir`
// held that `fill` did not write (another command's output, the user's own files) is
// carried over as hard links. The swap is renameat2(RENAME_EXCHANGE) where the file
// system has it, else two renames. If `fill` throws, `dir` is left as it was. A folder
// that holds the working directory cannot be swapped: its files are replaced one by one.
void replace_folder_atomically(const std::string& dir, const std::function<void(const std::string&)>& fill);

}  // namespace aloft::host
