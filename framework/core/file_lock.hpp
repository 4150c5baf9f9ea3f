// An exclusive lock on a file (flock), held for the object's lifetime: how
// concurrent runs share a cache entry (docs/sweeps.md, "Caches"). The first
// process to want an entry computes it while holding the entry's lock; the
// others wait, then read what it wrote. The kernel releases the lock when its
// process ends, however it ends.
#pragma once

#include <string>

namespace corrmp {

class FileLock {
 public:
  // Blocks until the lock on `path` (created if missing) is held. Throws
  // std::runtime_error naming the path when it cannot be opened.
  explicit FileLock(const std::string& path);
  ~FileLock();
  FileLock(const FileLock&) = delete;
  FileLock& operator=(const FileLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace corrmp
