// Folders a sweep writes into (its manifest, job logs, Slurm files): made up front, with one
// clear error when they cannot be, and removed again when the invocation that made them fails
// before its sweep has started (a submission sbatch refuses). docs/sweeps.md.
#pragma once

#include <filesystem>
#include <string>

namespace corrmp {

// Makes `folder` and its missing parents. Throws ConfigError "`option`: cannot make the folder
// F: why" when it cannot be made (a file in the way, no permission, a filesystem that takes no
// folders) or written in.
void make_sweep_folder(const std::filesystem::path& folder, const std::string& option);

// Removes at destruction, with everything in it, the topmost of `folder` and its parents that
// did not exist at construction (so nothing that was there before), unless keep() was called.
class NewFolderCleanup {
 public:
  explicit NewFolderCleanup(const std::filesystem::path& folder);
  ~NewFolderCleanup();
  NewFolderCleanup(const NewFolderCleanup&) = delete;
  NewFolderCleanup& operator=(const NewFolderCleanup&) = delete;

  void keep() { topmost_new_.clear(); }

 private:
  std::filesystem::path topmost_new_;  // empty: nothing to remove
};

}  // namespace corrmp
