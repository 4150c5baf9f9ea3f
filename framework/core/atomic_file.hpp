// Writing a file so that readers see the old content or the whole new one,
// never part of it: caches, model files and manifests (docs/sweeps.md,
// "Caches"). The bytes go to a temporary name of the writer's own in the same
// folder, "<path>.tmp.<host>.<pid>.<n>", created exclusively; every write is
// checked, the file is synced, renamed into place, and the folder is synced.
//
// Readers only ever open <path>: a temporary file is never read, even one a
// killed writer left behind. Such leftovers are removed by the next write of
// the same path on the same host once their process has ended; those of
// other hosts (a shared file system) are left alone, as their writer may
// still be running.
#pragma once

#include <string>

#include "core/file_error.hpp"

namespace corrmp {

// Throws FileError naming `path` when any step fails (a full disk, a missing
// folder, `path` being a directory); the temporary file is removed and `path`
// is left as it was.
void write_file_atomically(const std::string& path, const std::string& bytes);

// True when `name` (a file name, no folder) is one of write_file_atomically's
// temporary names for the file named `target` (no folder either).
bool is_temporary_name(const std::string& name, const std::string& target);

}  // namespace corrmp
