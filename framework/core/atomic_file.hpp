// Writing a file so that readers see the old content or the whole new one,
// never part of it: caches, model files and manifests (docs/sweeps.md,
// "Caches"). The bytes go to a temporary name of this process's own, every
// write is checked, the file is synced, then renamed into place.
#pragma once

#include <string>

namespace corrmp {

// Throws std::runtime_error naming `path` when any step fails (a full disk
// included); the temporary file is removed and `path` is left as it was.
void write_file_atomically(const std::string& path, const std::string& bytes);

}  // namespace corrmp
