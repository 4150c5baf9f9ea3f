// What a run records about where it came from: git commit and dirty flag of the
// source tree the binary was built from, host, and library versions (run.json).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace corrmp {

struct GitState {
  std::string commit = "unknown";
  bool dirty = false;
};

// The state of the source tree when this binary was built: what a run
// records. Generated on every build by cmake/build_info.cmake.
GitState build_git_state();

// The state of the source tree now ("unknown" commit where git or the tree is missing, as on
// a cluster node that has only the binary).
GitState source_git_state();

// A warning when the source tree is no longer the one the binary was built from (another
// commit, or uncommitted changes made or undone since), "" otherwise or when either state is
// unknown. Further changes to a tree that was already dirty at build time are not seen.
std::string source_change_warning(const GitState& built, const GitState& now);

// Name and version of each library linked into the framework.
std::vector<std::pair<std::string, std::string>> library_versions();

}  // namespace corrmp
